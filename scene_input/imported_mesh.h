// An imported primitive's triangles as a Mesh the model draws (SPEC 2.1):
// strips and fans expanded, the winding reversed under a negative
// determinant, flat normals where the file gives none, the back of a
// double-sided material added, and the smooth pieces the reference masks
// between. API-neutral: the backends and the reference read the result.
#pragma once

#include "lighting/mesh.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <optional>
#include <vector>

namespace scene_input {

// glTF 2.0 primitive modes that make triangles.
enum class TriangleMode { Triangles = 4, Strip = 5, Fan = 6 };

// The triangles of a strip or a fan as glTF 2.0 defines them (strip i:
// (i, i+1, i+2) for even i, (i, i+2, i+1) for odd; fan i: (i+1, i+2, 0)), or
// the list itself read three at a time. Triangles that repeat a vertex (the
// stitching of strips) are left out: they have no area.
std::vector<glm::u32vec3> trianglesOf(TriangleMode mode, const std::vector<std::uint32_t>& indices);

struct WorldPrimitive {
  std::vector<lighting::Vec3> positions;             // world space
  std::optional<std::vector<lighting::Vec3>> normals;  // world space, not yet normalised; absent: flat
  std::vector<glm::u32vec3> triangles;     // counter-clockwise when seen from the front in the file's frame
  bool reverseWinding = false;             // the world matrix has a negative determinant
  bool doubleSided = false;
};

// The mesh; `zeroNormals` counts vertices whose normal had no length (each
// replaced by the normalised sum of its triangles' area-weighted normals).
lighting::Mesh buildImportedMesh(WorldPrimitive primitive, std::size_t* zeroNormals = nullptr);

// Which smooth piece each triangle belongs to: triangles that meet at a point
// with the same normal there (to 2^-30 in each component, wherever the
// vertex is stored) are one piece,
// numbered in the order of their first triangle. A box of six flat faces has
// six, a sphere or a plane one.
std::vector<std::uint32_t> smoothPieces(const lighting::Mesh& mesh);

}  // namespace scene_input
