#include "lighting/cookie_slots.h"

namespace lighting {

CookieSlots assignCookieSlots(const Scene& scene, const LightSelection& selection) {
  CookieSlots slots;
  slots.slotOfLight.assign(scene.lights.size(), -1);
  auto take = [&](int light) {
    if (!scene.lights[light].cookie) return;
    const bool cube = scene.lights[light].type == LightType::Point;
    std::vector<int>& list = cube ? slots.cubeLights : slots.textureLights;
    const int most = cube ? kMaxCookieCubes : kMaxCookieTextures;
    if (int(list.size()) == most) {
      if (slots.overflow.empty())
        slots.overflow = "the kept lights have more than " + std::to_string(most) + (cube ? " cube" : " 2D") +
                         " cookies in one frame (light '" + scene.lights[light].name + "'), more than the slots";
      return;
    }
    slots.slotOfLight[light] = int(list.size());
    list.push_back(light);
  };
  for (int light : selection.packed.directional) take(light);
  for (int light : selection.packed.other) take(light);
  return slots;
}

}  // namespace lighting
