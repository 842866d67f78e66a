// The cookie block every backend uploads (SPEC 3.10), std140, built once
// here: per slot of lighting::CookieSlots, the affine map from the
// camera-relative position the shaders see to the light's cookie space, so
// that nothing large reaches float32 (SPEC 7's far-from-origin cases) and the
// shader's lookup is one matrix product and the SPEC 3.10 step of its kind.
#pragma once

#include "lighting/frame.h"
#include "lighting/gpu_packing.h"

namespace lighting {

enum class GpuCookieKind : int { None = 0, Directional = 1, Spot = 2, Point = 3 };

struct GpuCookie {
  // Camera-relative p (w = 1) to:
  //   directional: (u, v, 0, 1), u = dot(p_world, r) / w less an integer (the
  //     camera's share dot(camera, r) / w is wrapped in double: the sampler
  //     repeats, so only its fraction matters, and it stays small in float);
  //   spot: (q.x, q.y, q.z, 1), q = B (p_world - position), B the rows r, u, f;
  //   point: (p_world - position, 1), the cube's direction.
  GpuMat4 toCookie;
  GpuVec4 params;  // x: GpuCookieKind, y: spot 0.5 / tan(spot_angle / 2), z: the slot's texture index, w: 0
};
static_assert(sizeof(GpuCookie) == 80);

// 2D slots first (kMaxCookieTextures), then the cube slots (kMaxCookieCubes).
constexpr int kGpuCookieSlots = kMaxCookieTextures + kMaxCookieCubes;
struct GpuCookieBlock {
  GpuCookie cookies[kGpuCookieSlots];
};
static_assert(sizeof(GpuCookieBlock) == 480);

// The block of `frame`: unused slots have kind None.
GpuCookieBlock packCookieBlock(const Frame& frame);

// The packed block slot of a scene light's cookie, or -1 (what the shader's
// Light carries to find its cookie).
int cookieBlockSlot(const Frame& frame, int sceneLight);

}  // namespace lighting
