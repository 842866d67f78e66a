// withConstantComparisonsFolded on a module written word by word (SPIR-V 1.0,
// section 3: an instruction's first word is its word count << 16 | opcode):
// the comparisons of the chosen specialization constant with an integer
// constant, whichever side the constant is on, and logical operations of
// those alone become OpConstantTrue or OpConstantFalse; every other
// instruction stays as it was.
#include "shaders/spirv_constant_folding.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <stdexcept>
#include <vector>

namespace shaders {
namespace {

using Words = std::vector<std::uint32_t>;

constexpr std::uint32_t op(std::uint32_t words, std::uint32_t opcode) { return words << 16 | opcode; }

// Opcodes: OpTypeBool 20, OpTypeInt 21, OpConstantTrue 41, OpConstantFalse 42,
// OpConstant 43, OpSpecConstant 50, OpSpecConstantOp 52, OpDecorate 71;
// operations LogicalOr 166, LogicalAnd 167, LogicalNot 168, IEqual 170,
// INotEqual 171; decoration SpecId 1.
const Words kHeader = {0x07230203u, 0x00010000u, 0, 20, 0};
const Words kDeclarations = {
    op(4, 71), 5, 1, 22,  // OpDecorate %5 SpecId 22: the constant folded
    op(4, 71), 12, 1, 3,  // OpDecorate %12 SpecId 3: another one
    op(2, 20), 2,         // %2 = OpTypeBool
    op(4, 21), 3, 32, 1,  // %3 = OpTypeInt 32 signed
    op(4, 50), 3, 5, 0,   // %5 = OpSpecConstant %3 0
    op(4, 50), 3, 12, 0,  // %12 = OpSpecConstant %3 0
    op(4, 43), 3, 6, 4,   // %6 = OpConstant %3 4
    op(4, 43), 3, 7, 5,   // %7 = OpConstant %3 5
};
// Read after the comparisons: another constant's comparison, and a logical
// operation that reads it as well as a folded one, stay as they are.
const Words kUntouched = {
    op(6, 52), 2, 13, 170, 12, 6,  // %13 = OpSpecConstantOp IEqual %12 %6: another constant's
    op(6, 52), 2, 14, 167, 8, 13,  // %14 = OpSpecConstantOp LogicalAnd %8 %13
};

Words module(const Words& comparisons) {
  Words m = kHeader;
  m.insert(m.end(), kDeclarations.begin(), kDeclarations.end());
  m.insert(m.end(), comparisons.begin(), comparisons.end());
  m.insert(m.end(), kUntouched.begin(), kUntouched.end());
  return m;
}

const Words kComparisons = {
    op(6, 52), 2, 8, 170, 5, 6,    // %8 = %5 == 4
    op(6, 52), 2, 9, 170, 7, 5,    // %9 = 5 == %5
    op(6, 52), 2, 10, 171, 5, 6,   // %10 = %5 != 4
    op(5, 52), 2, 11, 168, 8,      // %11 = !%8
    op(6, 52), 2, 15, 166, 8, 9,   // %15 = %8 || %9
};

TEST(SpirvConstantFolding, ComparisonsWithTheConstantBecomeTrueOrFalse) {
  const Words whenFour = {op(3, 41), 2, 8, op(3, 42), 2, 9, op(3, 42), 2, 10, op(3, 42), 2, 11, op(3, 41), 2, 15};
  EXPECT_EQ(withConstantComparisonsFolded(module(kComparisons), 22, 4), module(whenFour));
  const Words whenFive = {op(3, 42), 2, 8, op(3, 41), 2, 9, op(3, 41), 2, 10, op(3, 41), 2, 11, op(3, 41), 2, 15};
  EXPECT_EQ(withConstantComparisonsFolded(module(kComparisons), 22, 5), module(whenFive));
  const Words whenSix = {op(3, 42), 2, 8, op(3, 42), 2, 9, op(3, 41), 2, 10, op(3, 41), 2, 11, op(3, 42), 2, 15};
  EXPECT_EQ(withConstantComparisonsFolded(module(kComparisons), 22, 6), module(whenSix));
}

TEST(SpirvConstantFolding, AModuleWithoutTheConstantIsUnchanged) {
  const Words m = module(kComparisons);
  EXPECT_EQ(withConstantComparisonsFolded(m, 7, 4), m);
}

TEST(SpirvConstantFolding, WhatIsNoSpirvIsRefused) {
  EXPECT_THROW(withConstantComparisonsFolded(Words{1, 2, 3, 4, 5, 6}, 22, 4), std::invalid_argument);
  Words truncated = module(kComparisons);
  truncated.pop_back();
  EXPECT_THROW(withConstantComparisonsFolded(truncated, 22, 4), std::invalid_argument);
}

}  // namespace
}  // namespace shaders
