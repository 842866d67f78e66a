// Where shadow-mask channels run short (docs/baking.md): for each texel of a
// lightmapped object, how many SPEC 5.3 candidates (mixed lights with shadows
// and shadow_strength > 0) reach its world position. The shadow mask has four
// channels, so a texel reached by more than four such lights is a conflict:
// at least one of them had to be demoted. `lightcts bake` draws this map as
// DIR/<object>.overlap.png with the fixed legend below.
#pragma once

#include "lighting/frame.h"

#include <array>
#include <cstdint>
#include <vector>

namespace baking {

constexpr int kOverlapChannelLimit = 4;  // the shadow mask's channels

struct OverlapMap {
  int resolution = 0;
  std::vector<int> counts;         // texel (i, j) at j * N + i, as in lighting::TexelMap
  int maxCount = 0;
  long long texelsOverLimit = 0;   // texels with a count above kOverlapChannelLimit
};

// A light reaches a point when the point lies strictly inside its range
// sphere (point and spot: |q - position| < range, where rangeAtt > 0);
// a directional light reaches everything.
OverlapMap mixedLightOverlap(const lighting::PreparedScene& prepared, int object);

using Rgb8 = std::array<std::uint8_t, 3>;
// The legend: 0 dark grey, 1 blue, 2 green, 3 yellow, 4 purple, more than 4
// red (the conflict).
Rgb8 overlapColour(int count);

}  // namespace baking
