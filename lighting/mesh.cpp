#include "lighting/mesh.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>

namespace lighting {
namespace {

void computeBounds(Mesh& mesh) {
  if (mesh.positions.empty()) return;
  mesh.boundsMin = mesh.boundsMax = mesh.positions.front();
  for (const Vec3& p : mesh.positions) {
    mesh.boundsMin = glm::min(mesh.boundsMin, p);
    mesh.boundsMax = glm::max(mesh.boundsMax, p);
  }
}

std::uint32_t addVertex(Mesh& mesh, const Vec3& position, const Vec3& normal) {
  mesh.positions.push_back(position);
  mesh.normals.push_back(normal);
  return static_cast<std::uint32_t>(mesh.positions.size() - 1);
}

void addTriangle(Mesh& mesh, std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t piece) {
  mesh.triangles.emplace_back(a, b, c);
  mesh.trianglePiece.push_back(piece);
}

// SPEC 2: vertex (i, j) at x = -sx/2 + sx*i/n, z = -sz/2 + sz*j/n; cell (i, j)
// has the triangles (v00, v01, v11) and (v00, v11, v10).
Mesh buildPlane(const MeshSpec& spec) {
  Mesh mesh;
  const int n = spec.subdivisions;
  const double sx = spec.planeSizeX, sz = spec.planeSizeZ;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      addVertex(mesh, Vec3(-sx / 2 + sx * i / n, 0.0, -sz / 2 + sz * j / n), Vec3(0, 1, 0));
  auto index = [n](int i, int j) { return static_cast<std::uint32_t>(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const auto v00 = index(i, j), v10 = index(i + 1, j), v01 = index(i, j + 1), v11 = index(i + 1, j + 1);
      addTriangle(mesh, v00, v01, v11, 0);
      addTriangle(mesh, v00, v11, v10, 0);
    }
  }
  return mesh;
}

// Rings run from the +Y pole (ring 0) to the -Y pole; segments go around Y. The
// seam column is duplicated so every quad has its own four vertices.
Mesh buildSphere(const MeshSpec& spec) {
  Mesh mesh;
  const int rings = spec.sphereRings, segments = spec.sphereSegments;
  for (int r = 0; r <= rings; ++r) {
    const double theta = std::numbers::pi * r / rings;
    for (int s = 0; s <= segments; ++s) {
      const double phi = 2.0 * std::numbers::pi * s / segments;
      // Exact poles and seam keep the surface closed in double precision.
      const double sinTheta = (r == 0 || r == rings) ? 0.0 : std::sin(theta);
      const double cosTheta = r == 0 ? 1.0 : (r == rings ? -1.0 : std::cos(theta));
      const double cosPhi = s == segments ? 1.0 : std::cos(phi);
      const double sinPhi = s == segments ? 0.0 : std::sin(phi);
      const Vec3 unit(sinTheta * cosPhi, cosTheta, sinTheta * sinPhi);
      addVertex(mesh, unit * spec.sphereRadius, unit);
    }
  }
  auto index = [segments](int r, int s) { return static_cast<std::uint32_t>(r * (segments + 1) + s); };
  for (int r = 0; r < rings; ++r) {
    for (int s = 0; s < segments; ++s) {
      const auto a = index(r, s), b = index(r + 1, s), c = index(r + 1, s + 1), d = index(r, s + 1);
      // With theta growing along b - a and phi along d - a, (a, c, b) and
      // (a, d, c) wind counter-clockwise seen from outside. At the poles one
      // of the two collapses to a point pair and is left out.
      if (r != rings - 1) addTriangle(mesh, a, c, b, 0);
      if (r != 0) addTriangle(mesh, a, d, c, 0);
    }
  }
  return mesh;
}

// Six faces with flat outward normals; each face's (u, v) satisfies cross(u, v) = n.
Mesh buildBox(const MeshSpec& spec) {
  struct Face {
    Vec3 n, u, v;
  };
  static const Face faces[6] = {
      {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}},  {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
      {{0, 1, 0}, {0, 0, 1}, {1, 0, 0}},  {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
      {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},  {{0, 0, -1}, {0, 1, 0}, {1, 0, 0}},
  };
  Mesh mesh;
  const Vec3 half = spec.boxSize * 0.5;
  for (std::uint8_t f = 0; f < 6; ++f) {
    const Face& face = faces[f];
    const Vec3 centre = face.n * half;
    const Vec3 du = face.u * half, dv = face.v * half;
    const auto p00 = addVertex(mesh, centre - du - dv, face.n);
    const auto p10 = addVertex(mesh, centre + du - dv, face.n);
    const auto p11 = addVertex(mesh, centre + du + dv, face.n);
    const auto p01 = addVertex(mesh, centre - du + dv, face.n);
    addTriangle(mesh, p00, p10, p11, f);
    addTriangle(mesh, p00, p11, p01, f);
  }
  return mesh;
}

// Each component rounded to float32 and back. GCC 12.2's SLP vectorizer
// (Debian 12, -O2) folds a pair of double -> float -> double conversions into
// nothing: measured here, x and y came back unrounded while z was rounded.
// Vectorizing this loop is switched off for GCC; the mesh tests check that
// every component is a float32 value.
#if defined(__GNUC__) && !defined(__clang__)
__attribute__((optimize("no-tree-slp-vectorize", "no-tree-loop-vectorize")))
#endif
void roundToFloat(std::vector<Vec3>& values) {
  for (Vec3& v : values) {
    v.x = double(float(v.x));
    v.y = double(float(v.y));
    v.z = double(float(v.z));
  }
}

}  // namespace

Mesh buildMesh(const MeshSpec& spec) {
  Mesh mesh;
  switch (spec.type) {
    case MeshType::Plane: mesh = buildPlane(spec); break;
    case MeshType::Sphere: mesh = buildSphere(spec); break;
    case MeshType::Box: mesh = buildBox(spec); break;
    case MeshType::Imported: return *spec.imported;  // world space, bounds known
  }
  roundToFloat(mesh.positions);
  roundToFloat(mesh.normals);
  computeBounds(mesh);
  return mesh;
}

}  // namespace lighting
