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
  double weight = 1;  // the fade weight (lighting/light_fade.h): 1 unless the scene fades; 0 when dropped
};

// The packed arrays every backend uploads, as scene light indices in packed order.
struct PackedLights {
  std::vector<int> directional;  // srp: up to 4 directional lights; legacy: empty
  std::vector<int> other;        // srp: up to 64 point/spot lights; legacy: up to 16 of any type
  // The fade weight of each packed light, parallel to the arrays above: it
  // scales finalColor in the packed data and in the (non-ideal) reference.
  // All 1 unless the scene sets pipeline.fade_last_lights.
  std::vector<double> directionalWeight;
  std::vector<double> otherWeight;
};

struct LightSelection {
  std::vector<VisibleLight> visible;  // every visible light, in SPEC 5.1 order
  PackedLights packed;

  // The weight of every scene light, indexed by scene light index: the kept
  // lights' weights, 0 for every light that is not kept.
  std::vector<double> weightsBySceneLight(std::size_t sceneLightCount) const;
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
