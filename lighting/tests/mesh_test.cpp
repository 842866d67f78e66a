// Meshes: the plane triangulation of SPEC 2 vertex by vertex, and for every
// mesh that each triangle winds counter-clockwise seen from outside (its
// geometric normal agrees with the vertex normals) and that the surface closes.
#include "lighting/mesh.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>

#include <map>

namespace lighting {
namespace {

TEST(PlaneMesh, VerticesAndTrianglesFollowSpec) {
  MeshSpec spec;
  spec.planeSizeX = 4;
  spec.planeSizeZ = 2;
  spec.subdivisions = 2;
  const Mesh m = buildMesh(spec);
  ASSERT_EQ(m.positions.size(), 9u);
  ASSERT_EQ(m.triangles.size(), 8u);
  // Vertex (i, j) at x = -sx/2 + sx i/n, z = -sz/2 + sz j/n; (1, 2) is index 2*3+1.
  EXPECT_EQ(m.positions[7], Vec3(0, 0, 1));
  EXPECT_EQ(m.positions[0], Vec3(-2, 0, -1));
  // Cell (0, 0): (v00, v01, v11) = (0, 3, 4) and (v00, v11, v10) = (0, 4, 1).
  EXPECT_EQ(m.triangles[0], glm::u32vec3(0, 3, 4));
  EXPECT_EQ(m.triangles[1], glm::u32vec3(0, 4, 1));
  EXPECT_EQ(m.boundsMin, Vec3(-2, 0, -1));
  EXPECT_EQ(m.boundsMax, Vec3(2, 0, 1));
}

void expectOutwardWinding(const Mesh& m) {
  for (const auto& t : m.triangles) {
    const Vec3 n = glm::cross(m.positions[t.y] - m.positions[t.x], m.positions[t.z] - m.positions[t.x]);
    ASSERT_GT(glm::length(n), 0.0) << "degenerate triangle";
    const Vec3 avg = m.normals[t.x] + m.normals[t.y] + m.normals[t.z];
    EXPECT_GT(glm::dot(n, avg), 0.0) << "triangle winds clockwise seen from outside";
  }
}

// Every edge of a closed surface is shared by exactly two triangles, once in
// each direction; compared by position so duplicated seam vertices count.
void expectClosed(const Mesh& m) {
  auto key = [&](std::uint32_t v) {
    const Vec3& p = m.positions[v];
    return std::tuple(p.x, p.y, p.z);
  };
  std::map<std::pair<std::tuple<double, double, double>, std::tuple<double, double, double>>, int> edges;
  for (const auto& t : m.triangles) {
    const std::uint32_t v[3] = {t.x, t.y, t.z};
    for (int e = 0; e < 3; ++e) edges[{key(v[e]), key(v[(e + 1) % 3])}]++;
  }
  for (const auto& [edge, n] : edges) {
    EXPECT_EQ(n, 1);
    EXPECT_EQ(edges.count({edge.second, edge.first}), 1u);
  }
}

TEST(SphereMesh, WindsOutwardAndCloses) {
  MeshSpec spec;
  spec.type = MeshType::Sphere;
  spec.sphereRadius = 2;
  spec.sphereSegments = 7;
  spec.sphereRings = 5;
  const Mesh m = buildMesh(spec);
  // Two triangles per quad except one per pole quad.
  EXPECT_EQ(m.triangles.size(), std::size_t(7 * (2 * 5 - 2)));
  expectOutwardWinding(m);
  expectClosed(m);
  // Each component is rounded to float32 (relative error <= 2^-24), so a
  // vector's length moves by at most 2^-24 of it.
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    EXPECT_NEAR(glm::length(m.positions[i]), 2.0, 2.0 * 0x1p-24);
    EXPECT_NEAR(glm::length(m.normals[i]), 1.0, 0x1p-24);
  }
}

// Whether a double holds a float32 value, read from its bits (not by
// converting, which the compiler bug the generator works around could fold
// away here too): a normal float's 24-bit significand leaves the double's
// low 29 bits zero, and its exponent lies within float's.
bool holdsFloat32(double v) {
  if (v == 0) return true;
  const std::uint64_t bits = std::bit_cast<std::uint64_t>(v);
  const int exponent = int((bits >> 52) & 0x7ff) - 1023;
  return (bits & ((std::uint64_t(1) << 29) - 1)) == 0 && exponent >= -126 && exponent <= 127;
}

// The generator's values are float32 values (what every backend draws),
// component by component: a compiler that folds the rounding away fails here.
TEST(Meshes, EveryComponentIsAFloat32Value) {
  EXPECT_FALSE(holdsFloat32(0.24999999999999997));  // sin(15 deg) cos(15 deg) in double
  EXPECT_TRUE(holdsFloat32(0.25));
  for (const MeshType type : {MeshType::Plane, MeshType::Sphere, MeshType::Box}) {
    MeshSpec spec;
    spec.type = type;
    spec.planeSizeX = 10.0 / 3;
    spec.subdivisions = 7;
    spec.sphereSegments = 24;
    spec.sphereRings = 12;
    spec.boxSize = {0.1, 0.3, 0.7};
    const Mesh m = buildMesh(spec);
    for (const auto* values : {&m.positions, &m.normals})
      for (const Vec3& v : *values)
        for (int c = 0; c < 3; ++c) ASSERT_TRUE(holdsFloat32(v[c])) << v[c] << ", mesh type " << int(type);
  }
}

TEST(BoxMesh, SixFlatFacesWindOutwardAndClose) {
  MeshSpec spec;
  spec.type = MeshType::Box;
  spec.boxSize = {1, 2, 3};
  const Mesh m = buildMesh(spec);
  EXPECT_EQ(m.triangles.size(), 12u);
  expectOutwardWinding(m);
  expectClosed(m);
  EXPECT_EQ(m.boundsMin, Vec3(-0.5, -1, -1.5));
  EXPECT_EQ(m.boundsMax, Vec3(0.5, 1, 1.5));
  for (std::size_t t = 0; t < m.triangles.size(); ++t) EXPECT_EQ(m.trianglePiece[t], t / 2);
}

}  // namespace
}  // namespace lighting
