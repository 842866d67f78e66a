#include "conformance/cpu_mutants.h"

#include "baking/bake.h"

#include <map>
#include <memory>
#include <mutex>
#include <utility>

namespace conformance {
namespace {

using PreparedPtr = std::shared_ptr<const lighting::PreparedScene>;

// demoted-light-still-lit: every demoted entry becomes an ordinary one
// without a channel. Light selection then keeps the light (it only skips
// baked and demoted lights) and packing gives it channel -1, while the maps
// in `baked` still hold its irradiance. Null when no light is demoted.
PreparedPtr demotedLightStillLit(const lighting::PreparedScene& prepared) {
  bool anyDemoted = false;
  for (bool demoted : prepared.shadowMask.demotedLight) anyDemoted |= demoted;
  if (!anyDemoted) return nullptr;
  auto copy = std::make_shared<lighting::PreparedScene>(prepared);
  for (lighting::ShadowMaskEntry& entry : copy->shadowMask.entries) entry.demoted = false;
  copy->shadowMask.demotedLight.assign(copy->shadowMask.demotedLight.size(), false);
  return copy;
}

// legacy-falloff-baked: the same scene with maps baked by the wrong falloff
// (the flag is part of the bake's cache key, so the model's bake is never
// overwritten). Null when the scene has no maps.
PreparedPtr legacyFalloffBaked(const lighting::PreparedScene& prepared) {
  if (!prepared.needsBake()) return nullptr;
  baking::BakeOptions options;
  options.mutantLegacyFalloff = true;
  return baking::withBake(prepared, baking::bakeScene(prepared, options));
}

PreparedPtr alter(const lighting::PreparedScene& prepared, shaders::Mutant mutant) {
  switch (mutant) {
    case shaders::Mutant::DemotedLightStillLit: return demotedLightStillLit(prepared);
    case shaders::Mutant::LegacyFalloffBaked: return legacyFalloffBaked(prepared);
    default: return nullptr;
  }
}

// The altered copies. The original is held weakly: a key whose original has
// died may name a new scene at the same address, so it is rebuilt.
struct AlteredScene {
  std::weak_ptr<const lighting::PreparedScene> original;
  PreparedPtr altered;  // null: the mutant does not apply to this scene
};

class AlteredScenes {
 public:
  PreparedPtr get(const PreparedPtr& prepared, shaders::Mutant mutant) {
    const Key key{prepared.get(), mutant};
    {
      std::lock_guard lock(mutex_);
      auto it = scenes_.find(key);
      if (it != scenes_.end() && it->second.original.lock() == prepared) return it->second.altered;
    }
    // Built outside the lock: a bake takes a while and runs on every core.
    AlteredScene entry{prepared, alter(*prepared, mutant)};
    std::lock_guard lock(mutex_);
    std::erase_if(scenes_, [](const auto& item) { return item.second.original.expired(); });
    return scenes_.insert_or_assign(key, std::move(entry)).first->second.altered;
  }

 private:
  using Key = std::pair<const lighting::PreparedScene*, shaders::Mutant>;
  std::mutex mutex_;
  std::map<Key, AlteredScene> scenes_;
};

AlteredScenes& alteredScenes() {
  static AlteredScenes scenes;
  return scenes;
}

}  // namespace

bool isCpuMutant(shaders::Mutant mutant) {
  return mutant == shaders::Mutant::DemotedLightStillLit || mutant == shaders::Mutant::LegacyFalloffBaked;
}

lighting::Frame cpuMutantFrame(const lighting::Frame& frame, shaders::Mutant mutant) {
  if (!isCpuMutant(mutant)) return frame;
  PreparedPtr altered = alteredScenes().get(frame.prepared, mutant);
  if (!altered) return frame;
  return lighting::prepareFrame(std::move(altered), frame.index);
}

}  // namespace conformance
