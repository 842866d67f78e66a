// The visible set of one frame, its order and the budgets (SPEC 5.1 and 4).
#pragma once

#include "lighting/camera_view.h"
#include "lighting/scene.h"
#include "lighting/shadow_mask_channels.h"

#include <vector>

namespace lighting {

constexpr int kSrpMaxDirectionalLights = 4;
constexpr int kSrpMaxOtherLights = 64;
constexpr int kLegacyMaxLights = 16;

struct VisibleLight {
  int light = -1;   // index in scene.lights
  int packed = -1;  // index in its kind's packed array, -1 when dropped by the budget
};

// The packed arrays every backend uploads, as scene light indices in packed order.
struct PackedLights {
  std::vector<int> directional;  // srp: up to 4 directional lights; legacy: empty
  std::vector<int> other;        // srp: up to 64 point/spot lights; legacy: up to 16 of any type
};

struct LightSelection {
  std::vector<VisibleLight> visible;  // every visible light, in SPEC 5.1 order
  PackedLights packed;
};

// True when a point/spot light's range sphere is not fully outside any frustum
// plane; directional lights are always visible (SPEC 5.1). The planes come
// from CameraView::frustumPlanes(), computed once per frame by the caller.
bool isLightVisible(const Light& light, const std::array<FrustumPlane, 6>& frustum);

// Lights with mode `baked`, and mixed lights demoted by the shadow-mask
// assignment, take no part.
LightSelection selectVisibleLights(const Scene& scene, const CameraView& view,
                                   const ShadowMaskAssignment& shadowMask);

}  // namespace lighting
