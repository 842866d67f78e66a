// Which triangle edges are open (WorldTriangle::openEdges): the mask treats a
// centre near one as near an edge (docs/tolerances.md "The mask").
#include "reference/world_triangles.h"

#include <gtest/gtest.h>

namespace reference {
namespace {

using lighting::Vec3;

// A unit square in the y = 0 plane as two triangles, its diagonal from
// (0, 0, 0) to (1, 0, 1); the second triangle's diagonal ends are its own
// vertices, moved by `seam` along x.
lighting::PreparedScene square(double seam) {
  lighting::ObjectGeometry g;
  g.mesh.positions = {{0, 0, 0}, {1, 0, 0}, {1, 0, 1},                  // triangle 0
                      {0 + seam, 0, 0}, {1 + seam, 0, 1}, {0, 0, 1}};   // triangle 1
  g.mesh.normals.assign(6, Vec3(0, 1, 0));
  g.mesh.triangles = {{0, 2, 1}, {3, 5, 4}};
  g.mesh.trianglePiece = {0, 0};
  lighting::PreparedScene prepared;
  prepared.objects.push_back(g);
  return prepared;
}

TEST(WorldTriangles, AnEdgeTwoTrianglesShareByPositionIsClosedThoughItsVerticesAreDuplicated) {
  const WorldTriangles world = buildWorldTriangles(square(0.0));
  ASSERT_EQ(world.triangles.size(), 2u);
  // Triangle 0's edges: 0-2 (the diagonal), 2-1, 1-0: the diagonal is shared.
  EXPECT_EQ(world.triangles[0].openEdges, 0b110);
  // Triangle 1's edges: 3-5, 5-4, 4-3 (the diagonal).
  EXPECT_EQ(world.triangles[1].openEdges, 0b011);
}

TEST(WorldTriangles, ZeroAndMinusZeroAreOnePosition) {
  // A sphere's pole vertices are (0, r, +-0) by the sign of sin(phi); the
  // glTF copy of the sphere writes them all as 0 and must mask alike.
  lighting::PreparedScene prepared = square(0.0);
  prepared.objects[0].mesh.positions[3] = Vec3(-0.0, -0.0, -0.0);
  const WorldTriangles world = buildWorldTriangles(prepared);
  EXPECT_EQ(world.triangles[0].openEdges, 0b110);
  EXPECT_EQ(world.triangles[1].openEdges, 0b011);
}

TEST(WorldTriangles, ASeamOfVerticesApartHoweverLittleIsOpen) {
  const WorldTriangles world = buildWorldTriangles(square(1e-6));
  EXPECT_EQ(world.triangles[0].openEdges, 0b111);
  EXPECT_EQ(world.triangles[1].openEdges, 0b111);
}

}  // namespace
}  // namespace reference
