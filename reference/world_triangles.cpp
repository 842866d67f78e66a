#include "reference/world_triangles.h"

#include <glm/geometric.hpp>

#include <array>
#include <cstring>
#include <tuple>
#include <unordered_map>

namespace reference {
namespace {

// An edge by its two end positions, in a fixed order, equal as doubles (a
// pole's vertices are 0 and -0 by the sign of sin(phi): one position).
struct EdgeKey {
  std::array<double, 6> ends;
  bool operator==(const EdgeKey&) const = default;
};
struct EdgeKeyHash {
  std::size_t operator()(const EdgeKey& key) const {
    std::size_t h = 0;
    for (double end : key.ends) {
      const double d = end + 0.0;  // -0 + 0 is +0: equal keys hash alike
      std::uint64_t bits;
      std::memcpy(&bits, &d, sizeof bits);
      h = (h ^ bits) * 0x100000001b3ull;
    }
    return h;
  }
};

EdgeKey edgeKey(const Vec3& a, const Vec3& b) {
  const bool ordered = std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
  const Vec3& p = ordered ? a : b;
  const Vec3& q = ordered ? b : a;
  return {{p.x, p.y, p.z, q.x, q.y, q.z}};
}

// WorldTriangle::openEdges of the object's triangles [first, end).
void markOpenEdges(const lighting::Mesh& mesh, std::vector<WorldTriangle>& triangles, std::size_t first) {
  std::unordered_map<EdgeKey, int, EdgeKeyHash> uses;
  auto keyOf = [&](const glm::u32vec3& t, int i) {
    return edgeKey(mesh.positions[t[i]], mesh.positions[t[(i + 1) % 3]]);
  };
  for (const glm::u32vec3& t : mesh.triangles)
    for (int i = 0; i < 3; ++i) ++uses[keyOf(t, i)];
  for (std::size_t n = 0; n < mesh.triangles.size(); ++n)
    for (int i = 0; i < 3; ++i)
      if (uses[keyOf(mesh.triangles[n], i)] == 1) triangles[first + n].openEdges |= std::uint8_t(1u << i);
}

}  // namespace

WorldTriangles buildWorldTriangles(const lighting::PreparedScene& prepared) {
  WorldTriangles world;
  for (int o = 0; o < int(prepared.objects.size()); ++o) {
    const lighting::ObjectGeometry& g = prepared.objects[o];
    const auto base = static_cast<std::uint32_t>(world.vertices.size());
    for (std::size_t v = 0; v < g.mesh.positions.size(); ++v) {
      world.vertices.push_back({g.transform.applyToPoint(g.mesh.positions[v]),
                                glm::normalize(g.transform.applyToNormal(g.mesh.normals[v])), o, g.mesh.positions[v],
                                g.mesh.normals[v]});
    }
    const std::size_t first = world.triangles.size();
    for (std::size_t t = 0; t < g.mesh.triangles.size(); ++t) {
      const auto& tri = g.mesh.triangles[t];
      WorldTriangle w;
      w.vertex[0] = base + tri.x;
      w.vertex[1] = base + tri.y;
      w.vertex[2] = base + tri.z;
      w.p0 = world.vertices[w.vertex[0]].position;
      w.p1 = world.vertices[w.vertex[1]].position;
      w.p2 = world.vertices[w.vertex[2]].position;
      w.object = o;
      w.piece = g.mesh.trianglePiece[t];
      world.triangles.push_back(w);
    }
    markOpenEdges(g.mesh, world.triangles, first);
  }
  return world;
}

}  // namespace reference
