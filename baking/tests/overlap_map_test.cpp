// The overlap map behind `lightcts bake`'s DIR/<object>.overlap.png: how many
// SPEC 5.3 candidates reach each texel centre.
#include "baking/overlap_map.h"
#include "baking/tests/test_scenes.h"

#include <gtest/gtest.h>

namespace baking::testing {
namespace {

// A 4 x 4 plane, 4 x 4 map: texel (i, j) centre at (-1.5 + i, 0, -1.5 + j).
TEST(OverlapMap, CountsCandidatesWithinRange) {
  Scene s;
  s.objects.push_back(lightmappedPlane(4, 4, 4));
  // Five candidates of range 1 at (-1.5, 0.5, -1.5): they reach texel (0, 0)
  // (d = 0.5) and not texel (1, 0) (d^2 = 1.25).
  for (int k = 0; k < 5; ++k) s.lights.push_back(mixedShadowed({-1.5, 0.5, -1.5}, 1, 1 + k));
  // Not candidates: realtime, mixed without shadows, mixed with strength 0, baked.
  s.lights.push_back(pointLight({-1.5, 0.5, -1.5}, 1, 1, LightMode::Realtime));
  Light noShadows = mixedShadowed({-1.5, 0.5, -1.5}, 1, 1);
  noShadows.shadows = false;
  s.lights.push_back(noShadows);
  Light noStrength = mixedShadowed({-1.5, 0.5, -1.5}, 1, 1);
  noStrength.shadowStrength = 0;
  s.lights.push_back(noStrength);
  s.lights.push_back(pointLight({-1.5, 0.5, -1.5}, 1, 1, LightMode::Baked));
  // A mixed shadowed directional light reaches every texel.
  Light sun = directionalLight(1, {0, -1, 0}, LightMode::Mixed);
  sun.shadows = true;
  s.lights.push_back(sun);

  const auto prepared = lighting::prepareScene(s);
  const OverlapMap map = mixedLightOverlap(*prepared, 0);
  ASSERT_EQ(map.resolution, 4);
  EXPECT_EQ(map.counts[0], 6);      // five points and the sun
  EXPECT_EQ(map.counts[1], 1);      // the sun only
  EXPECT_EQ(map.counts[15], 1);
  EXPECT_EQ(map.maxCount, 6);
  EXPECT_EQ(map.texelsOverLimit, 1);
}

TEST(OverlapMap, ObjectWithoutLightmapHasNoMap) {
  Scene s;
  s.objects.push_back(box({1, 1, 1}, {0, 0, 0}));
  const auto prepared = lighting::prepareScene(s);
  EXPECT_EQ(mixedLightOverlap(*prepared, 0).resolution, 0);
}

TEST(OverlapMap, LegendIsFixedAndConflictIsRed) {
  EXPECT_EQ(overlapColour(5), (Rgb8{255, 0, 0}));
  EXPECT_EQ(overlapColour(40), (Rgb8{255, 0, 0}));
  for (int a = 0; a <= 4; ++a) {
    EXPECT_NE(overlapColour(a), overlapColour(5));
    for (int b = a + 1; b <= 4; ++b) EXPECT_NE(overlapColour(a), overlapColour(b));
  }
}

}  // namespace
}  // namespace baking::testing
