// Shadow-mask channel assignment (SPEC 5.3): at bake time, independent of the
// camera. Mixed lights with shadows each need one of the four channels of the
// shadow mask; a light that overlaps four earlier holders is demoted (baked,
// never lit in real time).
#pragma once

#include "lighting/scene.h"

#include <vector>

namespace lighting {

constexpr int kShadowMaskChannels = 4;

struct ShadowMaskEntry {
  int light = -1;    // index in scene.lights
  int channel = -1;  // 0..3, or -1 when demoted
  bool demoted = false;
};

struct ShadowMaskAssignment {
  std::vector<ShadowMaskEntry> entries;  // the candidates, in SPEC 5.3 order
  std::vector<int> channelOfLight;       // per scene light: its channel, or -1
  std::vector<bool> demotedLight;        // per scene light
};

// Near-linear: earlier holders are found through a uniform grid over the
// candidates' centres (shadow_mask_channels.cpp, docs/performance.md); the
// result is exactly the greedy of SPEC 5.3.
ShadowMaskAssignment assignShadowMaskChannels(const Scene& scene);

// SPEC 3.6 and 5.3: a light lives in the lightmaps, never in real time, when its
// mode is `baked` or it is a mixed light this assignment demoted. The one
// definition that selection, the baker and the reference share.
bool isBakedLight(const Scene& scene, const ShadowMaskAssignment& assignment, int light);

// The greedy of SPEC 5.3 as written: every light tested against every earlier
// holder, O(n^2). The definition the grid version is tested against.
ShadowMaskAssignment assignShadowMaskChannelsBruteForce(const Scene& scene);

}  // namespace lighting
