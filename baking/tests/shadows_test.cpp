// Baked shadows, the shadow mask's channels, which lights are baked, and
// determinism. Geometry: an 8 x 8 plane at the origin with a 16 x 16 map
// (texel centres at -3.75 + 0.5 i), and a unit box centred at (0, 1, 0)
// (x, z in [-0.5, 0.5], y in [0.5, 1.5]). Texels (7, 7) and (8, 8) have
// centres (-0.25, 0, -0.25) and (0.25, 0, 0.25), right under the box.
#include "baking/tests/test_scenes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

namespace baking::testing {
namespace {

Scene planeAndBox() {
  Scene s;
  s.objects.push_back(lightmappedPlane(8, 8, 16));
  s.objects.push_back(box({1, 1, 1}, {0, 1, 0}));
  return s;
}

TEST(BakeShadows, BoxOccluderBlocksABakedLightUnderIt) {
  Scene s = planeAndBox();
  Light l = pointLight({0, 4, 0}, 20, 1, LightMode::Baked);
  l.shadows = true;
  s.lights.push_back(l);
  const auto baked = bakeUncached(s);
  const lighting::TexelMap& map = baked->objects[0].lightmap;
  EXPECT_EQ(texel(map, 7, 7, 0), 0.0f);
  EXPECT_EQ(texel(map, 8, 8, 0), 0.0f);
  // Texel (0, 0) at (-3.75, 0, -3.75): the ray to (0, 4, 0) crosses
  // y in [0.5, 1.5] at |x| >= 2.3, far from the box. ray = (3.75, 4, 3.75),
  // distSqr = 44.125, N.L = 4 / sqrt(44.125), rangeAtt = (1 - (44.125/400)^2)^2.
  const double distSqr = 44.125;
  const double rangeAtt = std::pow(1 - std::pow(distSqr / 400, 2), 2);
  const double e = 4 / std::sqrt(distSqr) * rangeAtt / distSqr;
  EXPECT_NEAR(texel(map, 0, 0, 0), e, 1e-6 * e);
  // Without shadows the box changes nothing.
  s.lights[0].shadows = false;
  EXPECT_GT(texel(bakeUncached(s)->objects[0].lightmap, 8, 8, 0), 0.0f);
}

TEST(BakeShadows, BackFacesBlockToo) {
  // A plane facing away from the light (rotated 180 about x) still blocks it.
  Scene s;
  s.objects.push_back(lightmappedPlane(8, 8, 16));
  lighting::Object roof = lightmappedPlane(2, 2, 0);
  roof.isStatic = false;
  roof.transform.translate = {0, 1, 0};
  roof.transform.rotateDeg = {180, 0, 0};
  s.objects.push_back(roof);
  Light l = directionalLight(1, {0, -1, 0}, LightMode::Baked);
  l.shadows = true;
  s.lights.push_back(l);
  const auto baked = bakeUncached(s);
  EXPECT_EQ(texel(baked->objects[0].lightmap, 8, 8, 0), 0.0f);
  EXPECT_NEAR(texel(baked->objects[0].lightmap, 0, 0, 0), 1.0, 1e-7);
}

TEST(BakeShadows, DirectionalShadowReachesToInfinity) {
  // The box is 1 unit up; a directional light is blocked however far away
  // its source would be.
  Scene s = planeAndBox();
  Light l = directionalLight(2, {0, -1, 0}, LightMode::Baked);
  l.shadows = true;
  s.lights.push_back(l);
  const auto baked = bakeUncached(s);
  EXPECT_EQ(texel(baked->objects[0].lightmap, 8, 8, 0), 0.0f);
  EXPECT_NEAR(texel(baked->objects[0].lightmap, 0, 0, 0), 2.0, 1e-7);
}

// Two mixed shadowed lights that overlap: "a" (intensity 4) comes first in
// SPEC 5.3's order and holds channel 0, "b" channel 1.
// Texel (8, 8): a's ray is blocked, b's (toward (3, 4, 3)) leaves the box's
// column before y = 0.5 (x = 0.25 + 2.75 * 0.125 = 0.59). Texel (7, 7): both
// blocked (b's ray is at x = 0.16 at y = 0.5).
Scene twoMixedLights() {
  Scene s = planeAndBox();
  s.lights.push_back(mixedShadowed({0, 4, 0}, 20, 4));
  s.lights.push_back(mixedShadowed({3, 4, 3}, 20, 1));
  return s;
}

TEST(BakeShadowMask, ChannelsHoldEachMixedLightsVisibility) {
  const Scene s = twoMixedLights();
  const auto prepared = lighting::prepareScene(s);
  ASSERT_EQ(prepared->shadowMask.channelOfLight, (std::vector<int>{0, 1}));
  const auto baked = bakeUncached(s);
  const lighting::TexelMap& mask = baked->objects[0].shadowMask;
  ASSERT_EQ(mask.resolution, 16);
  EXPECT_EQ(texel(mask, 8, 8, 0), 0.0f);
  EXPECT_EQ(texel(mask, 8, 8, 1), 1.0f);
  EXPECT_EQ(texel(mask, 7, 7, 0), 0.0f);
  EXPECT_EQ(texel(mask, 7, 7, 1), 0.0f);
  for (int c = 0; c < 2; ++c) EXPECT_EQ(texel(mask, 0, 0, c), 1.0f);
  // Channels 2 and 3 hold no light: 1 everywhere.
  for (int j = 0; j < 16; ++j)
    for (int i = 0; i < 16; ++i) {
      EXPECT_EQ(texel(mask, i, j, 2), 1.0f);
      EXPECT_EQ(texel(mask, i, j, 3), 1.0f);
    }
  // Mixed lights that keep a channel are lit in real time: not in the lightmap.
  for (float t : baked->objects[0].lightmap.texels) EXPECT_TRUE(t == 0.0f || t == 1.0f);  // alpha is 1
  EXPECT_EQ(texel(baked->objects[0].lightmap, 0, 0, 0), 0.0f);
}

TEST(BakeShadowMask, LightsSharingAChannelEachServeTheirOwnSphere) {
  // Two mixed lights 10 apart with range 3.5 do not overlap and both hold
  // channel 0 (SPEC 5.3). A 16 x 4 plane with a 32 x 32 map: texel (i, j) has
  // its centre at x = -7.75 + 0.5 i, z = -1.9375 + 0.125 j. Texel (5, 16) at
  // (-5.25, 0, 0.0625) lies under a box at (-5, 1, 0) that blocks the left
  // light; its ray to the right light crosses y = 0.5 at x = -3.54, clear of
  // the box. Inside the left light's sphere the channel must hold the left
  // light's visibility (0), whichever light comes last.
  Scene s;
  s.objects.push_back(lightmappedPlane(16, 4, 32));
  s.objects.push_back(box({1, 1, 1}, {-5, 1, 0}));
  s.lights.push_back(mixedShadowed({-5, 3, 0}, 3.5, 2));
  s.lights.push_back(mixedShadowed({5, 3, 0}, 3.5, 1));
  const auto prepared = lighting::prepareScene(s);
  ASSERT_EQ(prepared->shadowMask.channelOfLight, (std::vector<int>{0, 0}));
  const auto baked = bakeUncached(s);
  EXPECT_EQ(texel(baked->objects[0].shadowMask, 5, 16, 0), 0.0f);
  // Texel (26, 16) at (5.25, 0, 0.0625), in the right light's sphere: nothing
  // blocks the right light there.
  EXPECT_EQ(texel(baked->objects[0].shadowMask, 26, 16, 0), 1.0f);
  // A box under the right light darkens its texel (the left light's ray
  // from there would pass clear, at x = 3.54 for y = 0.5), and the left
  // texel is unchanged.
  s.objects.push_back(box({1, 1, 1}, {5, 1, 0}));
  const auto both = bakeUncached(s);
  EXPECT_EQ(texel(both->objects[0].shadowMask, 26, 16, 0), 0.0f);
  EXPECT_EQ(texel(both->objects[0].shadowMask, 5, 16, 0), 0.0f);
}

TEST(BakedLights, DemotedMixedLightIsBakedRealtimeAndKeptMixedAreNot) {
  // Five mixed shadowed lights at the same spot, intensities 5..1: the
  // dimmest overlaps four holders and is demoted (SPEC 5.3). A realtime
  // light right above the texel adds nothing to the map.
  Scene s;
  s.objects.push_back(lightmappedPlane(4, 4, 4));
  for (int k = 0; k < 5; ++k) s.lights.push_back(mixedShadowed({0.5, 2, 0.5}, 5, 5 - k));
  s.lights.push_back(pointLight({-0.5, 1, 0.5}, 5, 100, LightMode::Realtime));
  const auto prepared = lighting::prepareScene(s);
  ASSERT_TRUE(prepared->shadowMask.demotedLight[4]);
  for (int k = 0; k < 4; ++k) ASSERT_FALSE(prepared->shadowMask.demotedLight[std::size_t(k)]);
  const auto baked = bakeUncached(s);
  // Texel (1, 2) at (-0.5, 0, 0.5), as in falloff_test: the demoted light
  // (intensity 1) alone: N.L = 2/sqrt(5), rangeAtt 0.9216, distSqr 5.
  const double e = (2 / std::sqrt(5.0)) * 0.9216 / 5;
  EXPECT_NEAR(texel(baked->objects[0].lightmap, 1, 2, 0), e, 1e-6 * e);
  // Its channel: none; the four holders use all four, all visible here.
  for (int c = 0; c < 4; ++c) EXPECT_EQ(texel(baked->objects[0].shadowMask, 1, 2, c), 1.0f);
}

TEST(BakeDeterminism, OneThreadAndTwoThreadsGiveIdenticalBits) {
  Scene s = twoMixedLights();
  Light sun = directionalLight(0.7, {1, -2, 0.5}, LightMode::Baked, {1, 0.9, 0.8});
  sun.shadows = true;
  s.lights.push_back(sun);
  Light spot = pointLight({-2, 3, 1}, 9, 3, LightMode::Baked, {0.2, 1, 0.4});
  spot.type = LightType::Spot;
  spot.direction = glm::normalize(Vec3(0.3, -1, 0));
  spot.shadows = true;
  s.lights.push_back(spot);
  const auto one = bakeUncached(s, 1), two = bakeUncached(s, 2);
  for (const auto* b : {one.get(), two.get()}) ASSERT_EQ(b->objects[0].lightmap.resolution, 16);
  for (auto member : {&lighting::ObjectBake::lightmap, &lighting::ObjectBake::shadowMask}) {
    const auto& a = one->objects[0].*member;
    const auto& b = two->objects[0].*member;
    ASSERT_EQ(a.texels.size(), b.texels.size());
    EXPECT_EQ(std::memcmp(a.texels.data(), b.texels.data(), a.texels.size() * sizeof(float)), 0);
  }
  // Objects without a lightmap get empty maps.
  EXPECT_TRUE(one->objects[1].lightmap.empty());
  EXPECT_TRUE(one->objects[1].shadowMask.empty());
}

}  // namespace
}  // namespace baking::testing
