#include "shaders/spirv_constant_folding.h"

#include <algorithm>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>

namespace shaders {
namespace {

// SPIR-V 1.x, section 3: opcodes and the one decoration read here.
constexpr std::uint32_t kOpTypeInt = 21, kOpConstantTrue = 41, kOpConstantFalse = 42, kOpConstant = 43,
                        kOpSpecConstantOp = 52, kOpDecorate = 71, kOpLogicalEqual = 164, kOpLogicalNotEqual = 165,
                        kOpLogicalOr = 166, kOpLogicalAnd = 167, kOpLogicalNot = 168, kOpIEqual = 170,
                        kOpINotEqual = 171;
constexpr std::uint32_t kDecorationSpecId = 1;
constexpr std::size_t kHeaderWords = 5;

struct Instruction {
  std::uint32_t opcode;
  std::span<const std::uint32_t> words;  // the whole instruction, its first word included
};

// Calls `visit` for each instruction after the header.
template <class Visit>
void forEachInstruction(std::span<const std::uint32_t> spirv, Visit&& visit) {
  if (spirv.size() < kHeaderWords || spirv[0] != 0x07230203u) throw std::invalid_argument("not a SPIR-V module");
  for (std::size_t at = kHeaderWords; at < spirv.size();) {
    const std::uint32_t count = spirv[at] >> 16;
    if (count == 0 || at + count > spirv.size()) throw std::invalid_argument("a SPIR-V instruction runs past the module");
    visit(Instruction{spirv[at] & 0xffffu, spirv.subspan(at, count)});
    at += count;
  }
}

}  // namespace

std::vector<std::uint32_t> withConstantComparisonsFolded(std::span<const std::uint32_t> spirv,
                                                         std::uint32_t specId, std::int32_t value) {
  // First pass: the constant's id, and every 32-bit integer OpConstant.
  std::optional<std::uint32_t> constantId;
  std::set<std::uint32_t> int32Types;
  std::map<std::uint32_t, std::int32_t> int32Constants;
  forEachInstruction(spirv, [&](const Instruction& i) {
    if (i.opcode == kOpDecorate && i.words.size() == 4 && i.words[2] == kDecorationSpecId && i.words[3] == specId)
      constantId = i.words[1];
    if (i.opcode == kOpTypeInt && i.words.size() == 4 && i.words[2] == 32) int32Types.insert(i.words[1]);
    if (i.opcode == kOpConstant && i.words.size() == 4 && int32Types.count(i.words[1]))
      int32Constants[i.words[2]] = std::int32_t(i.words[3]);
  });
  std::vector<std::uint32_t> out(spirv.begin(), spirv.begin() + std::min(spirv.size(), kHeaderWords));
  std::map<std::uint32_t, bool> folded;  // result id -> its value, for the comparisons folded so far
  const auto emitConstant = [&](const Instruction& i, bool result) {
    out.insert(out.end(), {(3u << 16) | (result ? kOpConstantTrue : kOpConstantFalse), i.words[1], i.words[2]});
    folded[i.words[2]] = result;
  };
  forEachInstruction(spirv, [&](const Instruction& i) {
    // OpSpecConstantOp: result type, result id, the operation, its operands.
    // SPIR-V declares an id before its uses, so an operand folded is folded
    // before the instruction that uses it is read.
    const std::uint32_t operation = i.words.size() >= 5 ? i.words[3] : 0;
    if (constantId && i.opcode == kOpSpecConstantOp && i.words.size() == 6 &&
        (operation == kOpIEqual || operation == kOpINotEqual)) {
      const std::uint32_t a = i.words[4], b = i.words[5];
      const std::uint32_t other = a == *constantId ? b : b == *constantId ? a : 0;
      if (const auto literal = int32Constants.find(other); other != 0 && literal != int32Constants.end()) {
        const bool equal = literal->second == value;
        emitConstant(i, operation == kOpIEqual ? equal : !equal);
        return;
      }
    }
    // A logical operation on comparisons folded above (`ADMISSIBLE == A ||
    // ADMISSIBLE == B`) is constant too; one with any other operand is not.
    if (i.opcode == kOpSpecConstantOp && i.words.size() == 5 && operation == kOpLogicalNot &&
        folded.count(i.words[4])) {
      emitConstant(i, !folded[i.words[4]]);
      return;
    }
    if (i.opcode == kOpSpecConstantOp && i.words.size() == 6 && folded.count(i.words[4]) && folded.count(i.words[5])) {
      const bool a = folded[i.words[4]], b = folded[i.words[5]];
      switch (operation) {
        case kOpLogicalOr: emitConstant(i, a || b); return;
        case kOpLogicalAnd: emitConstant(i, a && b); return;
        case kOpLogicalEqual: emitConstant(i, a == b); return;
        case kOpLogicalNotEqual: emitConstant(i, a != b); return;
        default: break;
      }
    }
    out.insert(out.end(), i.words.begin(), i.words.end());
  });
  return out;
}

}  // namespace shaders
