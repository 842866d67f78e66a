#include "shaders/shader_variant.h"

namespace shaders {

const std::vector<MutantName>& mutantNames() {
  static const std::vector<MutantName> names = {
      {Mutant::DistanceClamp1em4, "distance-clamp-1e-4", "distSqr clamped at 1e-4 instead of 1e-5 (SPEC 3.2)"},
  };
  return names;
}

std::optional<Mutant> mutantFromName(std::string_view name) {
  if (name == "none") return Mutant::None;
  for (const MutantName& m : mutantNames())
    if (m.name == name) return m.mutant;
  return std::nullopt;
}

std::string_view mutantName(Mutant mutant) {
  for (const MutantName& m : mutantNames())
    if (m.mutant == mutant) return m.name;
  return "none";
}

}  // namespace shaders
