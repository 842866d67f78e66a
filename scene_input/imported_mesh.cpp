#include "scene_input/imported_mesh.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <algorithm>
#include <cstring>
#include <numeric>
#include <unordered_map>

namespace scene_input {

using namespace lighting;  // the model this folder reads scenes into
namespace {

// A normal whose squared length is within this of 1 is kept as the file
// wrote it. A float32 unit vector is only unit to about 2^-23; normalising it
// again in double would move it by a rounding, and every consumer (the
// reference, the vertex shaders) normalises the normal it interpolates anyway.
// Keeping it makes an import of the built-in meshes add nothing.
constexpr double kUnitLengthSlack = 0x1p-20;

Vec3 faceNormal(const Vec3& a, const Vec3& b, const Vec3& c) { return glm::cross(b - a, c - a); }

Vec3 unitOrZero(const Vec3& v) {
  const double length = glm::length(v);
  return length > 0 && std::isfinite(length) ? v / length : Vec3(0.0);
}

// Union-find over triangles, with path halving.
struct Components {
  explicit Components(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
  std::uint32_t find(std::uint32_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  }
  void join(std::uint32_t a, std::uint32_t b) {
    a = find(a), b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
  std::vector<std::uint32_t> parent;
};

// Two normals this close (each component) shade the same far below any
// tolerance: flat normals computed from different edges of one plane differ
// in their last bits, and must not split the plane into pieces.
constexpr double kSameNormal = 0x1p-30;

// The bits of a vertex's position: vertices at one point are compared by
// their normals.
struct PositionKey {
  double values[3];
  bool operator==(const PositionKey& o) const { return std::memcmp(values, o.values, sizeof values) == 0; }
};
struct PositionKeyHash {
  std::size_t operator()(const PositionKey& k) const {
    std::size_t h = 1469598103934665603ull;
    for (double v : k.values) {
      std::uint64_t bits;
      std::memcpy(&bits, &v, sizeof bits);
      h = (h ^ bits) * 1099511628211ull;
    }
    return h;
  }
};

}  // namespace

std::vector<glm::u32vec3> trianglesOf(TriangleMode mode, const std::vector<std::uint32_t>& indices) {
  std::vector<glm::u32vec3> triangles;
  auto add = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    if (a != b && b != c && a != c) triangles.emplace_back(a, b, c);
  };
  const std::size_t n = indices.size();
  switch (mode) {
    case TriangleMode::Triangles:
      for (std::size_t i = 0; i + 2 < n; i += 3) add(indices[i], indices[i + 1], indices[i + 2]);
      break;
    case TriangleMode::Strip:
      for (std::size_t i = 0; i + 2 < n; ++i) {
        if (i % 2 == 0) add(indices[i], indices[i + 1], indices[i + 2]);
        else add(indices[i], indices[i + 2], indices[i + 1]);
      }
      break;
    case TriangleMode::Fan:
      for (std::size_t i = 0; i + 2 < n; ++i) add(indices[i + 1], indices[i + 2], indices[0]);
      break;
  }
  return triangles;
}

Mesh buildImportedMesh(WorldPrimitive primitive, std::size_t* zeroNormals) {
  Mesh mesh;
  if (primitive.reverseWinding)
    for (glm::u32vec3& t : primitive.triangles) std::swap(t.y, t.z);
  if (!primitive.normals) {
    // Flat normals: every triangle gets its own three vertices.
    for (const glm::u32vec3& t : primitive.triangles) {
      const Vec3 &a = primitive.positions[t.x], &b = primitive.positions[t.y], &c = primitive.positions[t.z];
      const Vec3 n = unitOrZero(faceNormal(a, b, c));
      if (n == Vec3(0.0)) continue;  // no area: nothing to draw or hit
      const auto first = std::uint32_t(mesh.positions.size());
      for (const Vec3* p : {&a, &b, &c}) {
        mesh.positions.push_back(*p);
        mesh.normals.push_back(n);
      }
      mesh.triangles.emplace_back(first, first + 1, first + 2);
    }
  } else {
    mesh.positions = std::move(primitive.positions);
    mesh.normals = std::move(*primitive.normals);
    mesh.triangles = std::move(primitive.triangles);
    // A vertex without a usable normal takes the area-weighted normal of its triangles.
    std::vector<Vec3> fallback(mesh.normals.size(), Vec3(0.0));
    std::size_t missing = 0;
    for (Vec3& n : mesh.normals) {
      const double squared = glm::dot(n, n);
      if (!(squared > 0) || !std::isfinite(squared)) {
        n = Vec3(0.0);
        ++missing;
      } else if (std::abs(squared - 1) > kUnitLengthSlack) {
        n = unitOrZero(n);
      }
    }
    if (missing > 0) {
      for (const glm::u32vec3& t : mesh.triangles) {
        const Vec3 f = faceNormal(mesh.positions[t.x], mesh.positions[t.y], mesh.positions[t.z]);
        for (std::uint32_t v : {t.x, t.y, t.z}) fallback[v] += f;
      }
      for (std::size_t v = 0; v < mesh.normals.size(); ++v) {
        if (mesh.normals[v] != Vec3(0.0)) continue;
        mesh.normals[v] = unitOrZero(fallback[v]);
        if (mesh.normals[v] == Vec3(0.0)) mesh.normals[v] = Vec3(0, 1, 0);  // used by no triangle with area
      }
    }
    if (zeroNormals) *zeroNormals = missing;
  }
  if (primitive.doubleSided) {
    // The back: every vertex again with its normal negated, every triangle
    // reversed, so back-face culling (SPEC 1) still decides what is drawn.
    const auto n = std::uint32_t(mesh.positions.size());
    for (std::uint32_t v = 0; v < n; ++v) {
      mesh.positions.push_back(mesh.positions[v]);
      mesh.normals.push_back(-mesh.normals[v]);
    }
    const std::size_t front = mesh.triangles.size();
    for (std::size_t t = 0; t < front; ++t) {
      const glm::u32vec3 f = mesh.triangles[t];
      mesh.triangles.emplace_back(f.x + n, f.z + n, f.y + n);
    }
  }
  mesh.trianglePiece = smoothPieces(mesh);
  if (!mesh.positions.empty()) {
    mesh.boundsMin = mesh.boundsMax = mesh.positions.front();
    for (const Vec3& p : mesh.positions) {
      mesh.boundsMin = glm::min(mesh.boundsMin, p);
      mesh.boundsMax = glm::max(mesh.boundsMax, p);
    }
  }
  return mesh;
}

std::vector<std::uint32_t> smoothPieces(const Mesh& mesh) {
  // At each point, the normals met there so far and the first triangle that
  // brought each: a triangle whose vertex has one of them joins its piece.
  struct Seen {
    Vec3 normal;
    std::uint32_t triangle;
  };
  std::unordered_map<PositionKey, std::vector<Seen>, PositionKeyHash> atPoint;
  Components pieces(mesh.triangles.size());
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    for (std::uint32_t v : {mesh.triangles[t].x, mesh.triangles[t].y, mesh.triangles[t].z}) {
      const Vec3 &p = mesh.positions[v], &n = mesh.normals[v];
      // + 0.0 makes -0 and +0 one point.
      std::vector<Seen>& seen = atPoint[PositionKey{{p.x + 0.0, p.y + 0.0, p.z + 0.0}}];
      auto same = std::find_if(seen.begin(), seen.end(), [&](const Seen& s) {
        const Vec3 d = glm::abs(s.normal - n);
        return std::max({d.x, d.y, d.z}) <= kSameNormal;
      });
      if (same == seen.end()) seen.push_back({n, t});
      else pieces.join(same->triangle, t);
    }
  }
  // Number the pieces in the order of their first triangle.
  std::vector<std::uint32_t> number(mesh.triangles.size(), UINT32_MAX), piece(mesh.triangles.size());
  std::uint32_t next = 0;
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    std::uint32_t& n = number[pieces.find(t)];
    if (n == UINT32_MAX) n = next++;
    piece[t] = n;
  }
  return piece;
}

}  // namespace scene_input
