// SPEC 3.6 texel values worked out by hand: one baked light over a 4 x 4
// plane at the origin with a 4 x 4 lightmap. Texel (1, 2) has its centre at
// u = 1.5/4, v = 2.5/4, so local x = (u - 0.5) * 4 = -0.5, z = (v - 0.5) * 4
// = 0.5: world q = (-0.5, 0, 0.5), N = (0, 1, 0).
#include "baking/tests/test_scenes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace baking::testing {
namespace {

constexpr int kI = 1, kJ = 2;

Scene planeWith(const Light& light) {
  Scene s;
  s.objects.push_back(lightmappedPlane(4, 4, 4));
  s.lights.push_back(light);
  return s;
}

void expectTexelRgb(const Scene& s, double r, double g, double b) {
  const auto baked = bakeUncached(s);
  const lighting::TexelMap& map = baked->objects[0].lightmap;
  ASSERT_EQ(map.resolution, 4);
  EXPECT_NEAR(texel(map, kI, kJ, 0), r, 1e-6 * std::abs(r) + 1e-30);
  EXPECT_NEAR(texel(map, kI, kJ, 1), g, 1e-6 * std::abs(g) + 1e-30);
  EXPECT_NEAR(texel(map, kI, kJ, 2), b, 1e-6 * std::abs(b) + 1e-30);
  EXPECT_EQ(texel(map, kI, kJ, 3), 1.0f);
}

// Light at (0.5, 2, 0.5): ray = (1, 2, 0), distSqr = 5, d = sqrt(5),
// N.L = 2 / sqrt(5). finalColor = (1, 0.5, 0.25) * 2.
Light bakedPoint(double range, lighting::BakeFalloff falloff) {
  Light l = pointLight({0.5, 2, 0.5}, range, 2, LightMode::Baked, {1, 0.5, 0.25});
  l.bakeFalloff = falloff;
  return l;
}

TEST(BakeFalloff, InverseSquaredIsRangeAttOverDistSqr) {
  // range 5: invRangeSq = 1/25, rangeAtt = (1 - (5/25)^2)^2 = 0.96^2 = 0.9216.
  const double e = (2 / std::sqrt(5.0)) * 0.9216 / 5;
  expectTexelRgb(planeWith(bakedPoint(5, lighting::BakeFalloff::InverseSquared)), 2 * e, 1 * e, 0.5 * e);
}

TEST(BakeFalloff, InverseSquaredIsZeroBeyondRange) {
  // range 2 < d = sqrt(5): rangeAtt = saturate(1 - (5/4)^2)^2 = 0.
  expectTexelRgb(planeWith(bakedPoint(2, lighting::BakeFalloff::InverseSquared)), 0, 0, 0);
}

TEST(BakeFalloff, InverseSquaredNoRangeIsOneOverDistSqr) {
  // The range (2, less than d) plays no part: 1 / 5.
  const double e = (2 / std::sqrt(5.0)) / 5;
  expectTexelRgb(planeWith(bakedPoint(2, lighting::BakeFalloff::InverseSquaredNoRange)), 2 * e, e, 0.5 * e);
}

TEST(BakeFalloff, LegacyIsQuadraticInsideRange) {
  // range 5: 1 / (1 + 25 * 5 / 25) = 1/6.
  const double e = (2 / std::sqrt(5.0)) / 6;
  expectTexelRgb(planeWith(bakedPoint(5, lighting::BakeFalloff::Legacy)), 2 * e, e, 0.5 * e);
}

TEST(BakeFalloff, LegacyIsZeroOutsideRange) {
  expectTexelRgb(planeWith(bakedPoint(2, lighting::BakeFalloff::Legacy)), 0, 0, 0);
}

TEST(BakeFalloff, MutantLegacyFalloffBakesInverseSquaredLightsAsLegacy) {
  // The same light as InverseSquaredIsRangeAttOverDistSqr, baked with the
  // mutant: 1/6 instead of 0.9216/5. No-range lights are left alone.
  const Scene s = planeWith(bakedPoint(5, lighting::BakeFalloff::InverseSquared));
  const auto mutant = bakeUncached(s, 0, true);
  const double legacy = 2 * (2 / std::sqrt(5.0)) / 6;
  EXPECT_NEAR(texel(mutant->objects[0].lightmap, kI, kJ, 0), legacy, 1e-6 * legacy);

  const Scene noRange = planeWith(bakedPoint(2, lighting::BakeFalloff::InverseSquaredNoRange));
  const double e = 2 * (2 / std::sqrt(5.0)) / 5;
  EXPECT_NEAR(texel(bakeUncached(noRange, 0, true)->objects[0].lightmap, kI, kJ, 0), e, 1e-6 * e);
}

TEST(BakeFalloff, SpotLightTakesTheSpotTerm) {
  // Spot at (0.5, 2, 0.5) pointing down, outer 90, inner 30 degrees (srp
  // profile: the scene's inner angle). spotDir = (0, 1, 0), so
  // dot(spotDir, L) = 2 / sqrt(5). SPEC 3.3: cosOuter = cos(45 deg),
  // cosInner = cos(15 deg), a = 1 / (cosInner - cosOuter), b = -cosOuter a.
  Light l = bakedPoint(5, lighting::BakeFalloff::InverseSquared);
  l.type = LightType::Spot;
  l.direction = {0, -1, 0};
  l.spotAngleDeg = 90;
  l.innerSpotAngleDeg = 30;
  const double pi = std::numbers::pi;
  const double cosOuter = std::cos(45 * pi / 180), cosInner = std::cos(15 * pi / 180);
  const double a = 1 / (cosInner - cosOuter), b = -cosOuter * a;
  const double s = std::clamp((2 / std::sqrt(5.0)) * a + b, 0.0, 1.0);
  const double e = (2 / std::sqrt(5.0)) * 0.9216 / 5 * s * s;
  ASSERT_GT(s, 0.0);
  ASSERT_LT(s, 1.0);  // between the cones: the term matters
  expectTexelRgb(planeWith(l), 2 * e, e, 0.5 * e);
}

TEST(BakeFalloff, SpotLightWithoutInnerAngleUsesTheLegacyRule) {
  // SPEC 3.4: tan(ri) = 46/64 tan(45 deg) = 46/64.
  Light l = bakedPoint(5, lighting::BakeFalloff::InverseSquared);
  l.type = LightType::Spot;
  l.direction = {0, -1, 0};
  l.spotAngleDeg = 90;
  l.innerSpotAngleDeg.reset();
  const double cosOuter = std::cos(std::numbers::pi / 4), cosInner = std::cos(std::atan(46.0 / 64.0));
  const double a = 1 / (cosInner - cosOuter), b = -cosOuter * a;
  const double s = std::clamp((2 / std::sqrt(5.0)) * a + b, 0.0, 1.0);
  const double e = (2 / std::sqrt(5.0)) * 0.9216 / 5 * s * s;
  expectTexelRgb(planeWith(l), 2 * e, e, 0.5 * e);
}

TEST(BakeFalloff, DirectionalLightHasNoFalloff) {
  // Travelling along (0, -1, -1)/sqrt(2): L = (0, 1, 1)/sqrt(2), N.L = 1/sqrt(2),
  // the same on every texel.
  Scene s = planeWith(directionalLight(3, {0, -1, -1}, LightMode::Baked, {0.5, 1, 2}));
  const double e = 3 / std::sqrt(2.0);
  expectTexelRgb(s, 0.5 * e, e, 2 * e);
  const auto baked = bakeUncached(s);
  EXPECT_EQ(texel(baked->objects[0].lightmap, 0, 0, 1), texel(baked->objects[0].lightmap, 3, 3, 1));
}

TEST(BakeFalloff, LightOnTheTexelStaysFinite) {
  // At q itself: distSqr clamps to 1e-5 and L = 0, so N.L = 0 and E = 0.
  Light on = pointLight({-0.5, 0, 0.5}, 5, 1, LightMode::Baked);
  on.shadows = true;
  expectTexelRgb(planeWith(on), 0, 0, 0);
  // 1e-4 above q: distSqr = 1e-8 clamps to 1e-5, L = (0, 1e-4, 0) / sqrt(1e-5),
  // rangeAtt = (1 - (1e-5/25)^2)^2.
  Light above = pointLight({-0.5, 1e-4, 0.5}, 5, 1, LightMode::Baked);
  const double nl = 1e-4 / std::sqrt(1e-5);
  const double rangeAtt = std::pow(1 - std::pow(1e-5 / 25, 2), 2);
  const double e = nl * rangeAtt / 1e-5;
  expectTexelRgb(planeWith(above), e, e, e);
  for (const Light& l : {on, above}) {
    const auto baked = bakeUncached(planeWith(l));
    for (float t : baked->objects[0].lightmap.texels) EXPECT_TRUE(std::isfinite(t));
  }
}

TEST(BakeFalloff, HugeIntensityIsClampedToTheLargestFloat) {
  // 1e38 * 1e5 overflows float: stored as FLT_MAX, never infinity.
  Light l = pointLight({-0.5, 1e-4, 0.5}, 5, 1e38, LightMode::Baked);
  const auto baked = bakeUncached(planeWith(l));
  EXPECT_EQ(texel(baked->objects[0].lightmap, kI, kJ, 0), std::numeric_limits<float>::max());
}

}  // namespace
}  // namespace baking::testing
