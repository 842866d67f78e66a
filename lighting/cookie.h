// SPEC 3.10's light cookies in double precision: the light basis of 3.9,
// where a point looks up a light's cookie, and the bilinear sample at mip
// level 0 (repeat for directional, clamp to edge for spot, seamless cube for
// point). The reference calls these; the GPU copy is shaders/lighting.glsl.
#pragma once

#include "lighting/light_space.h"
#include "lighting/scene.h"

#include <array>

namespace lighting {

struct CookieCoordinates {
  bool outside = false;  // spot: q.z <= 0, where the cookie is 0
  int face = 0;          // point: the cube face, +X, -X, +Y, -Y, +Z, -Z = 0..5; 0 otherwise
  double u = 0, v = 0;   // directional: not wrapped (the sampler repeats); spot: not clamped
};
CookieCoordinates cookieCoordinates(const Light& light, const Vec3& p);

// A spot cookie's uv = 0.5 + scale q.xy / q.z: scale = 0.5 / tan(spot_angle / 2).
double spotCookieScale(const Light& spot);

// The cube face a direction selects and its (u, v) (light_space.h's
// cubeFacePoint; at a tie the tolerance admits either face, reference/cookie_bound.cpp).
CookieCoordinates cubeCoordinates(const Vec3& direction);

// The four texels and weights of a bilinear sample (taps in the order
// (i0, j0), (i1, j0), (i0, j1), (i1, j1)). A cube tap outside its face has
// been moved to the adjacent face (face edges), or is the corner.
struct CookieTap {
  int face = 0, i = 0, j = 0;
  bool corner = false;  // cube only: both coordinates outside the face
  double weight = 0;
};
std::array<CookieTap, 4> cookieTaps(const Light& light, const CookieCoordinates& at);

// The value of one tap: its texel, or at a cube corner the mean of the three
// texels that meet there (the reference's choice; the tolerance admits any of them).
double tapValue(const Cookie& cookie, const CookieTap& tap);

// The bilinear blend of the four taps.
double blendTaps(const Cookie& cookie, const std::array<CookieTap, 4>& taps);

// SPEC 3.10: the cookie's value at p (1 for a light without one).
double cookieValue(const Light& light, const Vec3& p);

}  // namespace lighting
