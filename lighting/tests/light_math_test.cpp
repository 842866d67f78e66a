// SPEC 3.2-3.4 at values derived by hand (closed forms in the comments).
#include "lighting/light_math.h"

#include <gtest/gtest.h>

#include <cmath>

namespace lighting {
namespace {

TEST(RangeAttenuation, AtHandDerivedDistances) {
  const double r = 4.0;
  const double inv = inverseRangeSquared(r);
  auto at = [&](double d) { return rangeAttenuation(d * d, inv); };
  EXPECT_DOUBLE_EQ(at(0.0), 1.0);                 // (1 - 0)^2
  EXPECT_DOUBLE_EQ(at(0.5 * r), 0.87890625);      // q = 1/4: (1 - 1/16)^2 = (15/16)^2
  EXPECT_DOUBLE_EQ(at(0.8 * r), 0.34857216);      // q = 0.64: (1 - 0.4096)^2 = 0.5904^2
  EXPECT_DOUBLE_EQ(at(r), 0.0);                   // (1 - 1)^2
  EXPECT_DOUBLE_EQ(at(1.0001 * r), 0.0);          // 1 - q^2 < 0 saturates to 0
}

TEST(RangeAttenuation, TinyRangeIsClampedNotInfinite) {
  // invRangeSq = 1 / max(range^2, 1e-5): range 1e-3 gives 1e5, not 1e6.
  EXPECT_DOUBLE_EQ(inverseRangeSquared(1e-3), 1e5);
  EXPECT_DOUBLE_EQ(inverseRangeSquared(2.0), 0.25);
}

TEST(SpotFactors, InnerThirtyOuterSixty) {
  // cosOuter = cos 30 deg, cosInner = cos 15 deg; a = 1/(cosInner - cosOuter), b = -cosOuter a.
  const SpotFactors f = spotFactors(60, 30);
  EXPECT_NEAR(f.a, 10.009967675098249, 1e-12);
  EXPECT_NEAR(f.b, -8.66888629769614, 1e-12);
  // At the outer edge the factor is 0, at the inner edge 1.
  EXPECT_NEAR(spotAttenuation(std::sqrt(3.0) / 2.0, f), 0.0, 1e-12);
  EXPECT_NEAR(spotAttenuation(std::cos(15.0 * M_PI / 180.0), f), 1.0, 1e-12);
}

TEST(SpotFactors, InnerZeroOuterNinetyHasClosedForm) {
  // cosOuter = 1/sqrt(2), cosInner = 1: a = 1/(1 - 1/sqrt2) = 2 + sqrt2, b = -(1 + sqrt2).
  const SpotFactors f = spotFactors(90, 0);
  EXPECT_NEAR(f.a, 2.0 + std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(f.b, -(1.0 + std::sqrt(2.0)), 1e-12);
}

TEST(SpotFactors, InnerEqualsOuterUsesTheMinimumSpan) {
  // cosInner - cosOuter = 0 is clamped to 0.001: a = 1000, b = -1000 cos(22.5 deg).
  const SpotFactors f = spotFactors(45, 45);
  EXPECT_DOUBLE_EQ(f.a, 1000.0);
  EXPECT_NEAR(f.b, -1000.0 * std::cos(22.5 * M_PI / 180.0), 1e-9);
  EXPECT_TRUE(std::isfinite(spotAttenuation(1.0, f)));
}

TEST(SpotFactors, PointLightsAreUnattenuated) {
  Light point;
  point.type = LightType::Point;
  const SpotFactors f = lightSpotFactors(point, Profile::Srp);
  EXPECT_EQ(f.a, 0.0);
  EXPECT_EQ(f.b, 1.0);
  EXPECT_EQ(spotAttenuation(-1.0, f), 1.0);
}

// SPEC 3.4: tan(ri) = 46/64 tan(ro); the values are the full inner angle
// 2 ri for the full outer angle 2 ro, from atan(0.71875 tan(ro)).
TEST(LegacyInnerAngle, AtOneSevenNinetyOneSeventyNineAndOneEighty) {
  Light spot;  // no inner angle: the legacy rule applies in both profiles
  auto inner = [&](double outer) {
    spot.spotAngleDeg = outer;
    return effectiveInnerSpotAngleDeg(spot, Profile::Srp);
  };
  EXPECT_NEAR(inner(1), 0.7187588198168539, 1e-10);
  EXPECT_NEAR(inner(7), 5.034276192057876, 1e-10);
  EXPECT_NEAR(inner(90), 2.0 * std::atan(0.71875) * 180.0 / M_PI, 1e-10);  // tan 45 = 1
  EXPECT_NEAR(inner(179), 178.6087286982559, 1e-9);
  EXPECT_EQ(inner(180), 180.0);  // ro = 90: ri = 90 exactly, no NaN
  const SpotFactors f = lightSpotFactors(spot, Profile::Srp);
  EXPECT_TRUE(std::isfinite(f.a) && std::isfinite(f.b));
  EXPECT_DOUBLE_EQ(f.a, 1000.0);  // cosInner = cosOuter = 0
  EXPECT_NEAR(f.b, 0.0, 1e-12);
}

TEST(LegacyInnerAngle, LegacyProfileIgnoresTheScenesInnerAngle) {
  Light spot;
  spot.spotAngleDeg = 90;
  spot.innerSpotAngleDeg = 10;
  EXPECT_EQ(effectiveInnerSpotAngleDeg(spot, Profile::Srp), 10.0);
  EXPECT_NEAR(effectiveInnerSpotAngleDeg(spot, Profile::Legacy), 71.41338280120577, 1e-10);
}

TEST(Luminance, Rec709Weights) {
  EXPECT_DOUBLE_EQ(luminance({1, 0, 0}), 0.2126);
  EXPECT_DOUBLE_EQ(luminance({0, 1, 0}), 0.7152);
  EXPECT_DOUBLE_EQ(luminance({0, 0, 1}), 0.0722);
  EXPECT_NEAR(luminance({1, 1, 1}), 1.0, 1e-15);
}

}  // namespace
}  // namespace lighting
