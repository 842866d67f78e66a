// Which kept light's cookie goes to which texture slot of a frame, decided
// once here for every backend (SPEC 3.10). Only kept lights (SPEC 5.1's
// packed arrays) with a cookie take a slot, in packed order: directional
// first, then the others. Directional and spot cookies share the 2D slots,
// point cookies have the cube slots.
#pragma once

#include "lighting/visible_lights.h"

#include <string>
#include <vector>

namespace lighting {

constexpr int kMaxCookieTextures = 4;  // 2D cookies (directional, spot) in one frame
constexpr int kMaxCookieCubes = 2;     // cube cookies (point) in one frame

struct CookieSlots {
  std::vector<int> textureLights;  // the scene light of each 2D slot
  std::vector<int> cubeLights;     // the scene light of each cube slot
  std::vector<int> slotOfLight;    // per scene light: its slot in its kind's list, -1 without one
  // Not empty when the kept lights have more cookies than the slots: the
  // backends report the frame NotSupported with this sentence.
  std::string overflow;
  bool any() const { return !textureLights.empty() || !cubeLights.empty(); }
};

CookieSlots assignCookieSlots(const Scene& scene, const LightSelection& selection);

}  // namespace lighting
