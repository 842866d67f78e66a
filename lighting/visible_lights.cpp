#include "lighting/visible_lights.h"

#include "lighting/light_fade.h"
#include "lighting/light_math.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <optional>
#include <utility>

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
  auto brightness = [&](int i) { return luminance(scene.lights[i].finalColor()); };
  auto distanceSquared = [&](int i) {
    const Vec3 d = scene.lights[i].position - view.camera.position;
    return glm::dot(d, d);
  };
  // (sort key, scene index), the key computed once per light rather than per
  // comparison (a comparison reading scene.lights misses the cache at 100k lights).
  std::vector<std::pair<double, int>> directionalKeys, otherKeys;
  for (int i = 0; i < int(scene.lights.size()); ++i) {
    const Light& l = scene.lights[i];
    if (isBakedLight(scene, shadowMask, i)) continue;
    if (!isLightVisible(l, frustum)) continue;
    if (l.type == LightType::Directional) {
      directionalKeys.emplace_back(brightness(i), i);
    } else {
      otherKeys.emplace_back(distanceSquared(i), i);
    }
  }
  // Directional by luminance(finalColor) descending; the others by squared
  // distance to the camera ascending; stable sorts over ascending scene
  // indices give ties to the lower index.
  std::stable_sort(directionalKeys.begin(), directionalKeys.end(),
                   [](const auto& a, const auto& b) { return a.first > b.first; });
  std::stable_sort(otherKeys.begin(), otherKeys.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<int> directional, other;
  directional.reserve(directionalKeys.size());
  other.reserve(otherKeys.size());
  for (const auto& [key, i] : directionalKeys) directional.push_back(i);
  for (const auto& [key, i] : otherKeys) other.push_back(i);

  LightSelection selection;
  selection.visible.reserve(directional.size() + other.size());
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

  // Fade weights (lighting/light_fade.h): directional lights keep 1 (their
  // order does not depend on the camera); the kept point/spot lights fade
  // toward the first dropped one, by squared distance.
  std::vector<double> keptDistanceSquared;
  std::optional<double> firstDropped;
  for (const VisibleLight& v : selection.visible) {
    if (scene.lights[v.light].type == LightType::Directional) continue;
    if (v.packed >= 0) {
      keptDistanceSquared.push_back(distanceSquared(v.light));
    } else if (!firstDropped) {
      firstDropped = distanceSquared(v.light);
    }
  }
  const std::vector<double> fade = fadeWeights(keptDistanceSquared, firstDropped, scene.pipeline.fadeLastLights);
  std::size_t nextFade = 0;
  for (VisibleLight& v : selection.visible) {
    if (v.packed < 0) {
      v.weight = 0.0;
    } else if (scene.lights[v.light].type != LightType::Directional) {
      v.weight = fade[nextFade++];
    }
  }
  selection.packed.directionalWeight.assign(selection.packed.directional.size(), 1.0);
  selection.packed.otherWeight.assign(selection.packed.other.size(), 1.0);
  for (const VisibleLight& v : selection.visible) {
    if (v.packed < 0) continue;
    const bool directionalArray =
        scene.pipeline.profile == Profile::Srp && scene.lights[v.light].type == LightType::Directional;
    (directionalArray ? selection.packed.directionalWeight : selection.packed.otherWeight)[v.packed] = v.weight;
  }
  return selection;
}

std::vector<double> LightSelection::weightsBySceneLight(std::size_t sceneLightCount) const {
  std::vector<double> weights(sceneLightCount, 0.0);
  for (const VisibleLight& v : visible) weights[v.light] = v.weight;
  return weights;
}

}  // namespace lighting
