// What both backends upload for a light's cookie (SPEC 3.10), decided once
// here: one 32-bit float per texel, the cookie's value (R32F: the value is
// stored exactly, and a bilinear lookup fetches one channel where RGBA32F
// would fetch four; on llvmpipe and lavapipe each channel of each of the four
// texels is a gather per fragment), and how the light's kind addresses them.
// shaders/cookies.glsl reads r.
#pragma once

#include "lighting/scene.h"

#include <vector>

namespace backends {

enum class CookieAddressing {
  Repeat,       // directional: tiled in both axes
  ClampToEdge,  // spot
  Cube,         // point: a seamless cube map, faces +X, -X, +Y, -Y, +Z, -Z
};
CookieAddressing cookieAddressing(const lighting::Light& light);

// Every face of `cookie`, face after face, each row by row from row 0 (v = 0
// is row 0 on both APIs, so nothing is flipped): the value, one float per texel.
std::vector<float> cookieTexels(const lighting::Cookie& cookie);

// A face's width (= height for a cube).
int cookieWidth(const lighting::Cookie& cookie);
int cookieHeight(const lighting::Cookie& cookie);

}  // namespace backends
