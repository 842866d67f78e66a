// The BVH against a brute-force loop over every triangle (an independent
// path), plus the face-culling and exclusion rules on one hand-placed quad.
#include "reference/bvh.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <optional>
#include <random>

namespace reference {
namespace {

using lighting::Ray;

WorldTriangles quadAtHeight(double y) {
  // Two triangles of the square [-1, 1]^2 at height y, front face up (+Y).
  WorldTriangles w;
  const Vec3 a(-1, y, -1), b(-1, y, 1), c(1, y, 1), d(1, y, -1);
  w.triangles.push_back({a, b, c, {0, 1, 2}, 0, 0});
  w.triangles.push_back({a, c, d, {0, 2, 3}, 0, 0});
  return w;
}

TEST(Bvh, HitsAQuadFromTheFrontOnly) {
  const WorldTriangles w = quadAtHeight(2);
  const Bvh bvh(w);
  const auto down = bvh.nearestHit({{0.25, 5, 0.5}, {0, -1, 0}}, 0, 100);
  ASSERT_TRUE(down);
  EXPECT_DOUBLE_EQ(down->t, 3.0);
  const WorldTriangle& t = w.triangles[down->triangle];
  const Vec3 p = (1 - down->b1 - down->b2) * t.p0 + down->b1 * t.p1 + down->b2 * t.p2;
  EXPECT_NEAR(glm::length(p - Vec3(0.25, 2, 0.5)), 0.0, 1e-15);
  // From below the quad shows its back: culled, unless asked otherwise.
  EXPECT_FALSE(bvh.nearestHit({{0, -5, 0.1}, {0, 1, 0}}, 0, 100));
  HitFilter both;
  both.frontFacesOnly = false;
  EXPECT_TRUE(bvh.nearestHit({{0, -5, 0.1}, {0, 1, 0}}, 0, 100, both));
  // tMax cuts it off; excluding the surface removes it.
  EXPECT_FALSE(bvh.nearestHit({{0.25, 5, 0.5}, {0, -1, 0}}, 0, 2.9));
  HitFilter exclude;
  exclude.excludeObject = 0;
  exclude.excludePiece = 0;
  EXPECT_FALSE(bvh.nearestHit({{0.25, 5, 0.5}, {0, -1, 0}}, 0, 100, exclude));
}

std::optional<std::pair<double, int>> bruteForce(const WorldTriangles& w, const Ray& ray) {
  std::optional<std::pair<double, int>> best;
  for (int i = 0; i < int(w.triangles.size()); ++i) {
    const WorldTriangle& t = w.triangles[i];
    // Plane of the triangle, then inside-outside by edge normals.
    const Vec3 n = glm::cross(t.p1 - t.p0, t.p2 - t.p0);
    const double denom = glm::dot(n, ray.direction);
    if (denom >= 0) continue;  // back face or parallel
    const double dist = glm::dot(n, t.p0 - ray.origin) / denom;
    if (dist <= 0) continue;
    const Vec3 p = ray.origin + dist * ray.direction;
    const bool inside = glm::dot(glm::cross(t.p1 - t.p0, p - t.p0), n) >= 0 &&
                        glm::dot(glm::cross(t.p2 - t.p1, p - t.p1), n) >= 0 &&
                        glm::dot(glm::cross(t.p0 - t.p2, p - t.p2), n) >= 0;
    if (inside && (!best || dist < best->first)) best = {{dist, i}};
  }
  return best;
}

TEST(Bvh, AgreesWithBruteForceOnRandomTriangleSoup) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> pos(-5, 5), small(-0.7, 0.7);
  WorldTriangles w;
  for (int i = 0; i < 3000; ++i) {
    const Vec3 c(pos(rng), pos(rng), pos(rng));
    w.triangles.push_back({c + Vec3(small(rng), small(rng), small(rng)), c + Vec3(small(rng), small(rng), small(rng)),
                           c + Vec3(small(rng), small(rng), small(rng)), {0, 0, 0}, i, 0});
  }
  const Bvh bvh(w);
  int hits = 0;
  for (int r = 0; r < 2000; ++r) {
    const Vec3 origin(pos(rng) * 2, pos(rng) * 2, pos(rng) * 2);
    const Vec3 target(pos(rng), pos(rng), pos(rng));
    const Ray ray{origin, glm::normalize(target - origin)};
    const auto expected = bruteForce(w, ray);
    const auto got = bvh.nearestHit(ray, 0, 1e9);
    ASSERT_EQ(expected.has_value(), got.has_value()) << "ray " << r;
    if (!expected) continue;
    ++hits;
    EXPECT_NEAR(got->t, expected->first, 1e-9) << "ray " << r;
  }
  EXPECT_GT(hits, 500);  // the soup is dense enough that the test means something
}

}  // namespace
}  // namespace reference
