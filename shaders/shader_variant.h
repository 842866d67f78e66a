// Which variant of the one set of shaders a backend builds. The shipped model
// is `specialised` with no mutant: features a frame does not use are switched
// off by specialization constants (shaders/lighting.glsl). The full shader and
// the mutants exist for tests only.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace shaders {

// Deliberately wrong variants of the model (SPEC 7, mutation check), selected
// by the specialization constant MUTANT. 0 is the model itself; no other
// value is ever a default. The numbers are shared with shaders/mutants.glsl.
enum class Mutant : int {
  None = 0,
  DistanceClamp1em4 = 1,  // distSqr clamped at 1e-4 instead of 1e-5 (SPEC 3.2)
};

struct MutantName {
  Mutant mutant;
  std::string_view name;  // the --mutant spelling
  std::string_view what;  // one line for listings and reports
};
const std::vector<MutantName>& mutantNames();
std::optional<Mutant> mutantFromName(std::string_view name);
std::string_view mutantName(Mutant mutant);

struct ShaderVariant {
  bool specialised = true;  // false: every feature on, whatever the frame uses
  Mutant mutant = Mutant::None;
};

}  // namespace shaders
