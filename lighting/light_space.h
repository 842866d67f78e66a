// The coordinate frames SPEC 3.9 and 3.10 share: a light's basis (its
// cookies and shadow maps are laid out in it) and the cube map's face
// selection and face coordinates, the table Vulkan and OpenGL share. One
// copy for cookies (cookie.cpp) and shadow maps (shadow_projection.cpp), so
// both agree on the tie rule at cube edges.
#pragma once

#include "lighting/scene.h"

namespace lighting {

// SPEC 3.9: f = direction, r = normalize(cross(f, up)), u = cross(r, f), with
// up = +Y, or +Z when |f.y| > 0.99.
struct LightBasis {
  Vec3 r, u, f;
};
LightBasis lightBasis(const Vec3& direction);
constexpr double kBasisUpSwitch = 0.99;

// Cube faces in the standard order +X, -X, +Y, -Y, +Z, -Z = 0..5.
constexpr int kCubeFaceCount = 6;

// Where a direction meets the cube: its face (the major axis; ties go to x,
// then y: Vulkan recommends z, then y, and allows any fixed rule, so at a tie
// a tolerance admits either face) and the face's (u, v) in [0, 1], by the
// "Cube Map Face Selection" table of Vulkan and OpenGL; `major` is |ma|.
struct CubeFacePoint {
  int face = 0;
  double u = 0, v = 0;
  double major = 0;
};
CubeFacePoint cubeFacePoint(const Vec3& direction);

// The inverse: the direction to (s, t) in [-1, 1] on `face` of the cube
// [-1, 1]^3 (s = 2u - 1, t = 2v - 1).
Vec3 cubeFaceDirection(int face, double s, double t);

// A face's frame: the direction of its major axis, and the world directions
// in which s and t grow. cubeFaceDirection(face, s, t) = axis + s sAxis + t tAxis.
struct CubeFaceFrame {
  Vec3 axis, sAxis, tAxis;
};
CubeFaceFrame cubeFaceFrame(int face);

// Texel (i, j) of an N x N face, with i or j possibly one texel outside it:
// the texel of the adjacent face across the edge (Vulkan's cube map edge
// handling). The texel inside the face next to the edge sits half a texel
// from it; its neighbour across the edge sits half a texel from the edge on
// the other face, at the same place along the edge. Both coordinates
// outside: a corner, returned clamped into the face with `corner` set (the
// three texels that meet there are then the caller's to weigh).
struct CubeTexel {
  int face = 0, i = 0, j = 0;
  bool corner = false;
};
CubeTexel cubeTexelAcrossEdge(int face, int i, int j, int n);

}  // namespace lighting
