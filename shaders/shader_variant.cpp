#include "shaders/shader_variant.h"

namespace shaders {

const std::vector<MutantName>& mutantNames() {
  static const std::vector<MutantName> names(kMutantNames.begin(), kMutantNames.end());
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

lighting::DepthCompare shadowLookupCompare(Mutant mutant) {
  return mutant == Mutant::ShadowCompareLess ? lighting::DepthCompare::Less : lighting::kShadowLookupCompare;
}

lighting::VolumeRule volumeRule(Mutant mutant) {
  return mutant == Mutant::PointVolumeOutsideOnly ? lighting::VolumeRule::OutsideOnlyMutant
                                                  : lighting::VolumeRule::Model;
}

}  // namespace shaders
