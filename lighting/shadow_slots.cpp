#include "lighting/shadow_slots.h"

namespace lighting {

ShadowSlots assignShadowSlots(const Scene& scene, const LightSelection& selection) {
  ShadowSlots slots;
  slots.slotOfLight.assign(scene.lights.size(), -1);
  auto take = [&](int light) {
    if (!scene.lights[light].shadowMap) return;
    const bool cube = scene.lights[light].type == LightType::Point;
    std::vector<ShadowProjection>& list = cube ? slots.cubes : slots.maps;
    const int most = cube ? kMaxShadowCubes : kMaxShadowMaps;
    if (int(list.size()) == most) {
      if (slots.overflow.empty())
        slots.overflow = "the kept lights have more than " + std::to_string(most) +
                         (cube ? " cube" : " 2D") + " shadow maps in one frame (light '" +
                         scene.lights[light].name + "'), more than the slots";
      return;
    }
    slots.slotOfLight[light] = int(list.size());
    list.push_back(shadowProjection(scene, light));
  };
  for (int light : selection.packed.directional) take(light);
  for (int light : selection.packed.other) take(light);
  return slots;
}

}  // namespace lighting
