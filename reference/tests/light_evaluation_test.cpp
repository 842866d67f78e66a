// The double evaluation of SPEC 3.1-3.2 at hand-derived points, and the shape
// of its error bound.
#include "reference/light_evaluation.h"

#include "lighting/tests/light_builders.h"

#include <gtest/gtest.h>

#include <cmath>

namespace reference {
namespace {

using namespace lighting;
using lighting::testing::pointLight;

Scene oneLight(Light light) {
  Scene s;
  s.lights.push_back(light);
  return s;
}

LightSum evaluate(const Scene& s, Vec3 p, Vec3 n) {
  LightEvaluator e(s, s.pipeline.profile);
  LightSum sum;
  e.accumulate({0}, p, n, PositionContext{{0, 10, 0}, 10}, sum);
  return sum;
}

TEST(LightEvaluation, PointLightStraightAbove) {
  // d = 1, range 2: rangeAtt = (1 - (1/4)^2)^2 = (15/16)^2; N.L = 1; / d^2 = 1.
  const Scene s = oneLight(pointLight({0, 1, 0}, 2, 2, LightMode::Realtime, {1, 0.5, 0.25}));
  const LightSum sum = evaluate(s, {0, 0, 0}, {0, 1, 0});
  EXPECT_DOUBLE_EQ(sum.value.r, 2 * 0.87890625);
  EXPECT_DOUBLE_EQ(sum.value.g, 1 * 0.87890625);
  EXPECT_DOUBLE_EQ(sum.value.b, 0.5 * 0.87890625);
  EXPECT_EQ(sum.evaluations, 1);
}

TEST(LightEvaluation, AFadeWeightScalesTheValueAndTheBound) {
  // The fade weight (lighting/light_fade.h) scales finalColor; the float32
  // data holds float(finalColor * weight), one rounding like finalColor alone,
  // so value and bound both scale by the weight (these colours are powers of
  // two), and weight 0 gives exactly 0 with no bound but the flush floor of
  // its operations.
  const Scene s = oneLight(pointLight({0, 1, 0}, 2, 2, LightMode::Realtime, {1, 0.5, 0.25}));
  const PositionContext where{{0, 10, 0}, 10};
  LightSum plain, quarter, zero;
  LightEvaluator(s, s.pipeline.profile).accumulate({0}, {0, 0, 0}, {0, 1, 0}, where, plain);
  LightEvaluator(s, s.pipeline.profile, {0.25}).accumulate({0}, {0, 0, 0}, {0, 1, 0}, where, quarter);
  LightEvaluator(s, s.pipeline.profile, {0.0}).accumulate({0}, {0, 0, 0}, {0, 1, 0}, where, zero);
  EXPECT_DOUBLE_EQ(quarter.value.r, 0.25 * 2 * 0.87890625);
  for (int c = 0; c < 3; ++c) {
    EXPECT_DOUBLE_EQ(quarter.value[c], 0.25 * plain.value[c]);
    EXPECT_DOUBLE_EQ(quarter.errorBound[c], 0.25 * plain.errorBound[c]);
  }
  EXPECT_EQ(zero.value, Vec3(0.0));
  for (int c = 0; c < 3; ++c) EXPECT_LT(zero.errorBound[c], 1e-36);
}

TEST(LightEvaluation, PointLightAtFortyFiveDegrees) {
  // Light at (1, 1, 0): d^2 = 2, N.L = 1/sqrt2, range 10: q = 2/100.
  const Scene s = oneLight(pointLight({1, 1, 0}, 10));
  const LightSum sum = evaluate(s, {0, 0, 0}, {0, 1, 0});
  const double rangeAtt = std::pow(1 - 0.02 * 0.02, 2);
  EXPECT_NEAR(sum.value.r, rangeAtt / std::sqrt(2.0) / 2.0, 1e-15);
}

TEST(LightEvaluation, LightOnTheSurfacePointGivesZeroNotNaN) {
  // d = 0: distSqr clamps to 1e-5, L = 0, so saturate(dot(N, L)) = 0.
  const Scene s = oneLight(pointLight({3, 0, 4}, 5));
  const LightSum sum = evaluate(s, {3, 0, 4}, {0, 1, 0});
  EXPECT_EQ(sum.value, Vec3(0.0));
  EXPECT_TRUE(std::isfinite(sum.errorBound.r));
}

TEST(LightEvaluation, SpotConeEdges) {
  // Spot straight down from height 1, outer 90 inner 0: a = 2 + sqrt2,
  // b = -(1 + sqrt2). Directly below: cos = 1 -> factor 1. At 45 degrees off
  // axis (the outer edge): 0.
  Light spot = pointLight({0, 1, 0}, 100);
  spot.type = LightType::Spot;
  spot.direction = {0, -1, 0};
  spot.spotAngleDeg = 90;
  spot.innerSpotAngleDeg = 0;
  const Scene s = oneLight(spot);
  const double below = evaluate(s, {0, 0, 0}, {0, 1, 0}).value.r;
  EXPECT_NEAR(below, std::pow(1 - 1e-8, 2), 1e-15);
  EXPECT_NEAR(evaluate(s, {1, 0, 0}, {0, 1, 0}).value.r, 0.0, 1e-15);
  // Halfway in cosine between the edges: cos = (1 + 1/sqrt2)/2 -> factor 1/4.
  const double c = (1 + 1 / std::sqrt(2.0)) / 2, x = std::sqrt(1 - c * c) / c;  // tan of that angle
  const double d2 = 1 + x * x;
  const double expected = 0.25 * c * std::pow(1 - (d2 / 1e4) * (d2 / 1e4), 2) / d2;
  EXPECT_NEAR(evaluate(s, {x, 0, 0}, {0, 1, 0}).value.r, expected, 1e-12);
}

TEST(LightEvaluation, DirectionalIsNDotLTimesColour) {
  Light sun;
  sun.type = LightType::Directional;
  sun.direction = {0, -0.6, -0.8};  // L = (0, 0.6, 0.8)
  sun.intensity = 3;
  const Scene s = oneLight(sun);
  EXPECT_NEAR(evaluate(s, {5, 0, 5}, {0, 1, 0}).value.g, 3 * 0.6, 1e-15);
  EXPECT_EQ(evaluate(s, {5, 0, 5}, {0, -1, 0}).value.g, 0.0);  // facing away: saturate clamps
}

// A light 1 m straight above, range 4: term = rangeAtt / d^2 with d^2 = 1.
// With exact inputs the bound is the operations' own: a few dozen ULPs. A
// position error e per component of p moves d^2 by up to 2 e (the vertical
// component) to first order, and the term, whose slope in d^2 is
// -(1 + 4 g q^2 / ...) about -1.03 relative here, by at least 2 e relative.
TEST(LightEvaluation, ErrorBoundIsTheOperationsAndThePositionsError) {
  const Scene s = oneLight(pointLight({0, 1, 0}, 4));
  LightEvaluator e(s, s.pipeline.profile);
  const SurfaceErrors exactInputs{0.0, 0.0};
  PositionContext where{{0, 10, 0}, 10};
  where.inputs = &exactInputs;
  LightSum exact;
  e.accumulate({0}, {0, 0, 0}, {0, 1, 0}, where, exact);
  EXPECT_GT(exact.errorBound.r, 0.0);
  EXPECT_LT(exact.errorBound.r, 100 * 0x1p-24 * exact.value.r);
  const SurfaceErrors positionOff{1e-4, 0.0};
  where.inputs = &positionOff;
  LightSum moved;
  e.accumulate({0}, {0, 0, 0}, {0, 1, 0}, where, moved);
  EXPECT_GT(moved.errorBound.r, 2e-4 * moved.value.r);
  EXPECT_LT(moved.errorBound.r, 3 * 2e-4 * moved.value.r);
}

TEST(LightEvaluation, ErrorBoundGrowsForALightInTheSurface) {
  // Light in the plane 0.05 away: exact N.L = 0, but float32 positions can
  // tilt L out of the plane; the bound must allow for it.
  const Scene s = oneLight(pointLight({0.05, 0, 0}, 4));
  const LightSum sum = evaluate(s, {0, 0, 0}, {0, 1, 0});
  EXPECT_EQ(sum.value.r, 0.0);
  EXPECT_GT(sum.errorBound.r, 1e-6);
}

}  // namespace
}  // namespace reference
