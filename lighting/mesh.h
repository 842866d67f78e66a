// The triangles every backend draws and the reference ray-casts (SPEC 2). One
// generator serves both, so they can only differ in arithmetic, never in shape.
// Triangles are counter-clockwise seen from outside (front faces, SPEC 1).
#pragma once

#include "lighting/scene.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace lighting {

struct Mesh {
  std::vector<Vec3> positions;        // local space
  std::vector<Vec3> normals;          // local space, unit length
  std::vector<glm::u32vec3> triangles;
  // Which smooth piece of the surface a triangle belongs to: 0 for planes and
  // spheres, the face (0..5) for boxes, smoothPieces() for imported meshes.
  // Shading is continuous inside a piece; the reference masks pixels near a
  // change of piece.
  std::vector<std::uint32_t> trianglePiece;
  Vec3 boundsMin{0, 0, 0};
  Vec3 boundsMax{0, 0, 0};
};

// The generated meshes hold float32 values (positions and normals rounded
// once, here): every backend draws float32 vertices, so the reference traces
// exactly the triangles they draw, and a mesh written to a glTF file (float32
// by the format) and imported again is the same mesh, bit for bit.
Mesh buildMesh(const MeshSpec& spec);

}  // namespace lighting
