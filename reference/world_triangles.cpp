#include "reference/world_triangles.h"

#include <glm/geometric.hpp>

namespace reference {

WorldTriangles buildWorldTriangles(const lighting::PreparedScene& prepared) {
  WorldTriangles world;
  for (int o = 0; o < int(prepared.objects.size()); ++o) {
    const lighting::ObjectGeometry& g = prepared.objects[o];
    const auto base = static_cast<std::uint32_t>(world.vertices.size());
    for (std::size_t v = 0; v < g.mesh.positions.size(); ++v) {
      world.vertices.push_back({g.transform.applyToPoint(g.mesh.positions[v]),
                                glm::normalize(g.transform.applyToNormal(g.mesh.normals[v])), o});
    }
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
  }
  return world;
}

}  // namespace reference
