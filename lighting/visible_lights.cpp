#include "lighting/visible_lights.h"

#include "lighting/light_math.h"

#include <glm/geometric.hpp>

#include <algorithm>

namespace lighting {

bool isLightVisible(const Light& light, const std::array<FrustumPlane, 6>& frustum) {
  if (light.type == LightType::Directional) return true;
  for (const FrustumPlane& plane : frustum)
    if (plane.signedDistance(light.position) < -light.range) return false;
  return true;
}

LightSelection selectVisibleLights(const Scene& scene, const CameraView& view,
                                   const ShadowMaskAssignment& shadowMask) {
  const std::array<FrustumPlane, 6> frustum = view.frustumPlanes();
  std::vector<int> directional, other;
  for (int i = 0; i < int(scene.lights.size()); ++i) {
    const Light& l = scene.lights[i];
    if (l.mode == LightMode::Baked || shadowMask.demotedLight[i]) continue;
    if (!isLightVisible(l, frustum)) continue;
    (l.type == LightType::Directional ? directional : other).push_back(i);
  }
  // Directional by luminance(finalColor) descending; the others by squared
  // distance to the camera ascending; stable sorts give ties to the lower index.
  auto brightness = [&](int i) { return luminance(scene.lights[i].finalColor()); };
  auto distanceSquared = [&](int i) {
    const Vec3 d = scene.lights[i].position - view.camera.position;
    return glm::dot(d, d);
  };
  std::stable_sort(directional.begin(), directional.end(),
                   [&](int a, int b) { return brightness(a) > brightness(b); });
  std::stable_sort(other.begin(), other.end(),
                   [&](int a, int b) { return distanceSquared(a) < distanceSquared(b); });

  LightSelection selection;
  auto keep = [&](int light, std::vector<int>& packedArray, std::size_t limit) {
    int packed = -1;
    if (packedArray.size() < limit) {
      packed = int(packedArray.size());
      packedArray.push_back(light);
    }
    selection.visible.push_back({light, packed});
  };
  if (scene.pipeline.profile == Profile::Srp) {
    for (int i : directional) keep(i, selection.packed.directional, kSrpMaxDirectionalLights);
    for (int i : other) keep(i, selection.packed.other, kSrpMaxOtherLights);
  } else {
    // Legacy: one budget of 16 over the combined order, directional first.
    for (int i : directional) keep(i, selection.packed.other, kLegacyMaxLights);
    for (int i : other) keep(i, selection.packed.other, kLegacyMaxLights);
  }
  return selection;
}

}  // namespace lighting
