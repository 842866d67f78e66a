// One integer specialization constant's comparisons folded into the SPIR-V
// itself, for a Vulkan driver that compiles the code a specialization
// constant switches off.
//
// The admissible variants' build chooses its variant with ADMISSIBLE, and
// every build its mutant with MUTANT: each `ADMISSIBLE == ADMISSIBLE_<NAME>`
// or `MUTANT == MUTANT_<NAME>` is an OpSpecConstantOp. A driver may fold it
// at pipeline creation; SwiftShader does not (its optimiser folds no
// OpSpecConstantOp), so it compiles every variant's code into each variant's
// pipeline, several times the time of that variant's code alone. A
// variant or a mutant is lightcts's own deliberate implementation, not what
// a driver is conformance-tested on, so its pipelines get their build with
// the choice already constant; the pipelines of the model itself, which every
// conformance test runs, get the model's build as it is.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace shaders {

// `spirv` with every OpSpecConstantOp IEqual or INotEqual between the
// specialization constant of SpecId `specId` and a 32-bit integer
// OpConstant, and every LogicalNot, LogicalOr, LogicalAnd, LogicalEqual or
// LogicalNotEqual of such comparisons alone, replaced by OpConstantTrue or
// OpConstantFalse, as if the constant were `value`. Everything else, the
// constant itself and any expression that also reads another specialization
// constant included, is unchanged.
std::vector<std::uint32_t> withConstantComparisonsFolded(std::span<const std::uint32_t> spirv,
                                                         std::uint32_t specId, std::int32_t value);

}  // namespace shaders
