// Which kept light's shadow map goes to which depth-texture slot of a frame,
// decided once here for every backend (SPEC 3.9), the way cookie_slots.h
// does for cookies. Only kept lights (SPEC 5.1's packed arrays) with a shadow
// map take a slot, in packed order: directional first, then the others.
// Directional and spot maps share the 2D slots; point lights have the cube
// slots. Each slot's geometry is its light's ShadowProjection.
#pragma once

#include "lighting/shadow_projection.h"
#include "lighting/visible_lights.h"

#include <string>
#include <vector>

namespace lighting {

constexpr int kMaxShadowMaps = 4;   // 2D maps (directional, spot) in one frame
constexpr int kMaxShadowCubes = 2;  // cube maps (point) in one frame

struct ShadowSlots {
  std::vector<ShadowProjection> maps;   // the 2D slots, in slot order
  std::vector<ShadowProjection> cubes;  // the cube slots
  std::vector<int> slotOfLight;         // per scene light: its slot in its kind's list, -1 without one
  // Not empty when the kept lights have more shadow maps than the slots: the
  // backends report the frame NotSupported with this sentence.
  std::string overflow;
  bool any() const { return !maps.empty() || !cubes.empty(); }
};

ShadowSlots assignShadowSlots(const Scene& scene, const LightSelection& selection);

}  // namespace lighting
