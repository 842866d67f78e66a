// A bounding-volume hierarchy over world triangles, for the reference's rays
// (and the baker's shadow rays later). Built once per scene; read-only after,
// so any number of threads may trace at once.
#pragma once

#include "lighting/camera_view.h"
#include "reference/world_triangles.h"

#include <functional>
#include <optional>
#include <vector>

namespace reference {

struct RayHit {
  double t = 0;             // distance along the (unit) ray direction
  int triangle = -1;        // index in WorldTriangles::triangles
  double b1 = 0, b2 = 0;    // barycentrics of p1 and p2; p0 has 1 - b1 - b2
};

// Which hits count. Culling back faces is the rasteriser's rule (SPEC 1).
struct HitFilter {
  bool frontFacesOnly = true;
  int excludeObject = -1;   // with excludePiece: skip one surface (depth-tie queries)
  int excludePiece = -1;
};

class Bvh {
 public:
  explicit Bvh(const WorldTriangles& world);

  // The nearest accepted hit with tMin < t <= tMax.
  std::optional<RayHit> nearestHit(const lighting::Ray& ray, double tMin, double tMax,
                                   const HitFilter& filter = {}) const;

  const WorldTriangles& world() const { return world_; }

 private:
  struct Node {
    Vec3 boundsMin, boundsMax;
    int first = 0;  // leaf: first entry in order_; inner: index of the left child
    int right = 0;  // inner: index of the right child
    int count = 0;  // triangles in a leaf; 0 for an inner node
  };
  int build(int first, int count, int depth);

  const WorldTriangles& world_;
  std::vector<int> order_;  // triangle indices, leaves own contiguous ranges
  std::vector<Node> nodes_;
};

}  // namespace reference
