// SPEC 3.6's visibility test, shared by the baker (baking/bake.cpp) and the
// reference's real-time evaluation of baked lights (baked_lights_realtime.cpp):
// a ray from q + 1e-3 N toward the light, blocked by any triangle of the scene
// (front or back face) before the light, or before infinity for a directional one.
#pragma once

#include "lighting/scene.h"
#include "reference/bvh.h"

namespace reference {

// SPEC 3.6: shadow rays start 1e-3 along the normal, off the surface itself.
constexpr double kShadowRayOffset = 1e-3;

// 1 when nothing blocks the way from q + kShadowRayOffset * N toward `light`,
// else 0; 1 for a light without `shadows`.
double lightVisibility(const Bvh& bvh, const lighting::Light& light, const Vec3& q, const Vec3& N);

}  // namespace reference
