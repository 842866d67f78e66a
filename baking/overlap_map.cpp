#include "baking/overlap_map.h"

#include <glm/geometric.hpp>

#include <algorithm>

namespace baking {

OverlapMap mixedLightOverlap(const lighting::PreparedScene& prepared, int object) {
  const lighting::Object& obj = prepared.scene.objects[std::size_t(object)];
  const lighting::ObjectGeometry& geometry = prepared.objects[std::size_t(object)];
  OverlapMap map;
  if (!obj.hasLightmap()) return map;
  const int n = obj.lightmapResolution;
  map.resolution = n;
  map.counts.assign(std::size_t(n) * std::size_t(n), 0);
  // The candidates are exactly the entries of the assignment, demoted or not.
  std::vector<const lighting::Light*> candidates;
  for (const lighting::ShadowMaskEntry& entry : prepared.shadowMask.entries)
    candidates.push_back(&prepared.scene.lights[std::size_t(entry.light)]);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const lighting::Vec3 q = geometry.transform.applyToPoint(lighting::planeTexelCentreLocal(obj.mesh, n, i, j));
      int count = 0;
      for (const lighting::Light* light : candidates) {
        if (light->type == lighting::LightType::Directional) {
          ++count;
        } else {
          const lighting::Vec3 ray = light->position - q;
          if (glm::dot(ray, ray) < light->range * light->range) ++count;
        }
      }
      map.counts[std::size_t(j) * std::size_t(n) + std::size_t(i)] = count;
      map.maxCount = std::max(map.maxCount, count);
      if (count > kOverlapChannelLimit) ++map.texelsOverLimit;
    }
  return map;
}

Rgb8 overlapColour(int count) {
  static constexpr std::array<Rgb8, kOverlapChannelLimit + 1> kLegend = {{
      {48, 48, 48},    // 0: no mixed shadowed light
      {40, 90, 230},   // 1: blue
      {30, 170, 70},   // 2: green
      {235, 200, 20},  // 3: yellow
      {150, 70, 210},  // 4: purple, every channel in use
  }};
  if (count < 0) count = 0;
  if (count > kOverlapChannelLimit) return {255, 0, 0};  // red: more lights than channels
  return kLegend[std::size_t(count)];
}

}  // namespace baking
