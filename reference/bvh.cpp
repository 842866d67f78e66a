#include "reference/bvh.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <limits>

namespace reference {
namespace {

constexpr int kMaxLeafTriangles = 4;
constexpr int kMaxDepth = 64;

Vec3 centroid(const WorldTriangle& t) { return (t.p0 + t.p1 + t.p2) / 3.0; }

// Möller-Trumbore in double. det > 0 means the ray meets the triangle's
// counter-clockwise (front) side: det = -dot(direction, cross(e1, e2)).
bool intersectTriangle(const lighting::Ray& ray, const WorldTriangle& tri, double& t, double& b1, double& b2,
                       bool frontFacesOnly) {
  const Vec3 e1 = tri.p1 - tri.p0, e2 = tri.p2 - tri.p0;
  const Vec3 pvec = glm::cross(ray.direction, e2);
  const double det = glm::dot(e1, pvec);
  if (frontFacesOnly ? det <= 0.0 : det == 0.0) return false;
  const double inv = 1.0 / det;
  const Vec3 tvec = ray.origin - tri.p0;
  b1 = glm::dot(tvec, pvec) * inv;
  if (b1 < 0.0 || b1 > 1.0) return false;
  const Vec3 qvec = glm::cross(tvec, e1);
  b2 = glm::dot(ray.direction, qvec) * inv;
  if (b2 < 0.0 || b1 + b2 > 1.0) return false;
  t = glm::dot(e2, qvec) * inv;
  return true;
}

// Slab test; returns the entry distance or +inf when the box is missed.
double enterBox(const lighting::Ray& ray, const Vec3& invDir, const Vec3& lo, const Vec3& hi, double tMax) {
  double t0 = 0.0, t1 = tMax;
  for (int a = 0; a < 3; ++a) {
    double tn = (lo[a] - ray.origin[a]) * invDir[a];
    double tf = (hi[a] - ray.origin[a]) * invDir[a];
    if (tn > tf) std::swap(tn, tf);
    // NaN (0 * inf on a slab boundary) must not reject the box.
    if (tn > t0) t0 = tn;
    if (tf < t1) t1 = tf;
    if (t0 > t1) return std::numeric_limits<double>::infinity();
  }
  return t0;
}

}  // namespace

Bvh::Bvh(const WorldTriangles& world) : world_(world) {
  order_.resize(world.triangles.size());
  for (int i = 0; i < int(order_.size()); ++i) order_[i] = i;
  if (!order_.empty()) {
    nodes_.reserve(2 * order_.size() / kMaxLeafTriangles + 1);
    build(0, int(order_.size()), 0);
  }
}

int Bvh::build(int first, int count, int depth) {
  const int index = int(nodes_.size());
  nodes_.push_back({});
  Vec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  Vec3 cLo = lo, cHi = hi;
  for (int i = first; i < first + count; ++i) {
    const WorldTriangle& t = world_.triangles[order_[i]];
    for (const Vec3& p : {t.p0, t.p1, t.p2}) {
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
    const Vec3 c = centroid(t);
    cLo = glm::min(cLo, c);
    cHi = glm::max(cHi, c);
  }
  nodes_[index].boundsMin = lo;
  nodes_[index].boundsMax = hi;
  const Vec3 extent = cHi - cLo;
  const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
  if (count <= kMaxLeafTriangles || depth >= kMaxDepth || extent[axis] <= 0.0) {
    nodes_[index].first = first;
    nodes_[index].count = count;
    return index;
  }
  // Median split along the widest centroid axis: balanced, and plenty fast for
  // a reference that favours clarity.
  const int mid = first + count / 2;
  std::nth_element(order_.begin() + first, order_.begin() + mid, order_.begin() + first + count,
                   [&](int a, int b) { return centroid(world_.triangles[a])[axis] < centroid(world_.triangles[b])[axis]; });
  const int left = build(first, mid - first, depth + 1);
  const int right = build(mid, first + count - mid, depth + 1);
  nodes_[index].first = left;
  nodes_[index].right = right;
  nodes_[index].count = 0;
  return index;
}

std::optional<RayHit> Bvh::nearestHit(const lighting::Ray& ray, double tMin, double tMax,
                                      const HitFilter& filter) const {
  if (nodes_.empty()) return std::nullopt;
  const Vec3 invDir = 1.0 / ray.direction;
  std::optional<RayHit> best;
  double bestT = tMax;
  struct Pending {
    int node;
    double entry;  // where the ray enters the node's box
  };
  Pending stack[2 * kMaxDepth + 2];
  int top = 0;
  const double rootEntry = enterBox(ray, invDir, nodes_[0].boundsMin, nodes_[0].boundsMax, bestT);
  if (rootEntry <= bestT) stack[top++] = {0, rootEntry};
  while (top > 0) {
    const Pending pending = stack[--top];
    if (pending.entry > bestT) continue;  // a nearer hit was found meanwhile
    const Node& node = nodes_[pending.node];
    if (node.count > 0) {
      for (int i = node.first; i < node.first + node.count; ++i) {
        const WorldTriangle& tri = world_.triangles[order_[i]];
        if (tri.object == filter.excludeObject && tri.piece == filter.excludePiece) continue;
        double t, b1, b2;
        if (intersectTriangle(ray, tri, t, b1, b2, filter.frontFacesOnly) && t > tMin && t <= bestT) {
          bestT = t;
          best = RayHit{t, order_[i], b1, b2};
        }
      }
      continue;
    }
    // Push the farther child first so the nearer one is visited first and
    // bestT shrinks early.
    Pending near{node.first, enterBox(ray, invDir, nodes_[node.first].boundsMin, nodes_[node.first].boundsMax, bestT)};
    Pending far{node.right, enterBox(ray, invDir, nodes_[node.right].boundsMin, nodes_[node.right].boundsMax, bestT)};
    if (far.entry < near.entry) std::swap(near, far);
    if (far.entry <= bestT) stack[top++] = far;
    if (near.entry <= bestT) stack[top++] = near;
  }
  return best;
}

}  // namespace reference
