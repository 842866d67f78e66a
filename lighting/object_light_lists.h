// Per-object light lists (SPEC 5.2): which kept lights touch an object, ordered
// by importance, with the total `count` and the first 8 packed indices.
#pragma once

#include "lighting/scene.h"
#include "lighting/visible_lights.h"

#include <vector>

namespace lighting {

constexpr int kMaxLightsPerObject = 8;

struct BoundingSphere {
  Vec3 centre{0, 0, 0};
  double radius = 0;
};

struct ObjectLightList {
  int count = 0;             // every candidate; may exceed 8
  std::vector<int> indices;  // packed indices of the first min(count, 8)
};

// Candidates: kept point/spot lights with |p - c| <= range + R; in the legacy
// profile kept directional lights too, first, in their global order.
std::vector<ObjectLightList> buildObjectLightLists(const Scene& scene, const LightSelection& selection,
                                                   const std::vector<BoundingSphere>& objectBounds);

}  // namespace lighting
