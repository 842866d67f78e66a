// The frame's meshes flattened to world-space triangles in double precision,
// with what the reference needs to shade a hit: which object and which smooth
// piece it belongs to, and its vertices' world normals.
#pragma once

#include "lighting/frame.h"

#include <cstdint>
#include <vector>

namespace reference {

using lighting::Vec3;

struct WorldTriangle {
  Vec3 p0, p1, p2;           // counter-clockwise seen from the front
  std::uint32_t vertex[3];   // indices into WorldTriangles::vertices
  int object = -1;
  int piece = 0;             // Mesh::trianglePiece
};

struct WorldVertex {
  Vec3 position;
  Vec3 normal;  // rotated by R and normalised (SPEC 1, SPEC 4 vertex lights)
  int object = -1;
};

struct WorldTriangles {
  std::vector<WorldTriangle> triangles;
  std::vector<WorldVertex> vertices;
};

WorldTriangles buildWorldTriangles(const lighting::PreparedScene& prepared);

}  // namespace reference
