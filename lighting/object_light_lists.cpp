#include "lighting/object_light_lists.h"

#include "lighting/light_math.h"

#include <glm/geometric.hpp>

#include <algorithm>

namespace lighting {
namespace {

struct Candidate {
  int packed;
  double importance;
};

// importance = luminance(finalColor) * rangeAtt(d^2) / max(d^2, 1e-5), d = |p - c|.
double importance(const Light& light, const BoundingSphere& bounds) {
  const Vec3 ray = light.position - bounds.centre;
  const double d2 = glm::dot(ray, ray);
  return luminance(light.finalColor()) * rangeAttenuation(d2, inverseRangeSquared(light.range)) /
         std::max(d2, kMinDistanceSquared);
}

bool touches(const Light& light, const BoundingSphere& bounds) {
  return glm::length(light.position - bounds.centre) <= light.range + bounds.radius;
}

ObjectLightList listForObject(const Scene& scene, const std::vector<int>& packed,
                              const BoundingSphere& bounds) {
  std::vector<int> directional;   // packed indices, in packed (global) order
  std::vector<Candidate> local;
  for (int p = 0; p < int(packed.size()); ++p) {
    const Light& light = scene.lights[packed[p]];
    if (light.type == LightType::Directional) {
      directional.push_back(p);
    } else if (touches(light, bounds)) {
      local.push_back({p, importance(light, bounds)});
    }
  }
  // Descending importance; the stable sort over packed order gives ties to the
  // lower packed index.
  std::stable_sort(local.begin(), local.end(),
                   [](const Candidate& a, const Candidate& b) { return a.importance > b.importance; });
  ObjectLightList list;
  list.count = int(directional.size() + local.size());
  for (int p : directional)
    if (int(list.indices.size()) < kMaxLightsPerObject) list.indices.push_back(p);
  for (const Candidate& c : local)
    if (int(list.indices.size()) < kMaxLightsPerObject) list.indices.push_back(c.packed);
  return list;
}

}  // namespace

std::vector<ObjectLightList> buildObjectLightLists(const Scene& scene, const LightSelection& selection,
                                                   const std::vector<BoundingSphere>& objectBounds) {
  // In srp the lists index the point/spot array only, which holds no
  // directional light; in legacy the one array holds every kind.
  std::vector<ObjectLightList> lists;
  lists.reserve(objectBounds.size());
  for (const BoundingSphere& bounds : objectBounds)
    lists.push_back(listForObject(scene, selection.packed.other, bounds));
  return lists;
}

}  // namespace lighting
