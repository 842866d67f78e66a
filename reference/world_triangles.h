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
  // Bit i: the edge from vertex i to vertex (i + 1) % 3 is no other triangle
  // of the object's, by position: its border, or a seam the mesh never
  // welds (two vertices apart, however little). Vulkan promises exactly-once
  // coverage only along "a common edge (with identical endpoints)", so a
  // device may open a crack along a seam (docs/tolerances.md "The mask").
  std::uint8_t openEdges = 0;
};

struct WorldVertex {
  Vec3 position;
  Vec3 normal;  // rotated by R and normalised (SPEC 1, SPEC 4 vertex lights)
  int object = -1;
  Vec3 local;        // the mesh's position and normal, as the vertex stage gets them
  Vec3 localNormal;
};

struct WorldTriangles {
  std::vector<WorldTriangle> triangles;
  std::vector<WorldVertex> vertices;
};

WorldTriangles buildWorldTriangles(const lighting::PreparedScene& prepared);

}  // namespace reference
