#include "shaders/shader_variant.h"

#include <algorithm>
#include <stdexcept>
#include <string>

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

const std::vector<AdmissibleName>& admissibleNames() {
  static const std::vector<AdmissibleName> names(kAdmissibleNames.begin(), kAdmissibleNames.end());
  return names;
}

std::optional<Admissible> admissibleFromName(std::string_view name) {
  if (name == "none") return Admissible::None;
  for (const AdmissibleName& a : admissibleNames())
    if (a.name == name) return a.variant;
  return std::nullopt;
}

std::string_view admissibleName(Admissible variant) {
  for (const AdmissibleName& a : admissibleNames())
    if (a.variant == variant) return a.name;
  return "none";
}

const AdmissibleName& admissibleEntry(Admissible variant) {
  for (const AdmissibleName& a : admissibleNames())
    if (a.variant == variant) return a;
  throw std::invalid_argument("no admissible variant " + std::to_string(int(variant)));
}

bool admissibleRealisedOn(Admissible variant, std::string_view api) {
  if (variant == Admissible::None) return true;
  switch (admissibleEntry(variant).apis) {
    case AdmissibleApis::All: return true;
    case AdmissibleApis::Vulkan: return api == "vulkan";
    case AdmissibleApis::None: return false;
  }
  return false;
}

lighting::DepthCompare shadowLookupCompare(Mutant mutant) {
  return mutant == Mutant::ShadowCompareLess ? lighting::DepthCompare::Less : lighting::kShadowLookupCompare;
}

std::vector<lighting::LightVolume> lightVolumesInBlendOrder(const lighting::Frame& frame, const ShaderVariant& variant) {
  std::vector<lighting::LightVolume> volumes = lighting::lightVolumes(frame);
  if (variant.admissible == Admissible::LightsReversed) std::reverse(volumes.begin(), volumes.end());
  return volumes;
}

lighting::VolumeRule volumeRule(Mutant mutant) {
  return mutant == Mutant::PointVolumeOutsideOnly ? lighting::VolumeRule::OutsideOnlyMutant
                                                  : lighting::VolumeRule::Model;
}

}  // namespace shaders
