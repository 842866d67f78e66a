// The two-term fit (reports/two_term_limit.h) against hand-made curves: points
// exactly on t = a P + b L give back a and b with zero residual; points off
// the line give the residual its definition computes; degenerate curves give
// no fit.
#include "reports/two_term_limit.h"

#include <gtest/gtest.h>

#include <cmath>

namespace reports {
namespace {

// 640x360 pixels, 1..64 lights per pixel, a = 2e-6 ms/pixel, b = 5e-7 ms/pixel-light.
std::vector<TwoTermPoint> exactCurve() {
  const double pixels = 640.0 * 360.0, a = 2e-6, b = 5e-7;
  std::vector<TwoTermPoint> points;
  for (const double lights : {1.0, 2.0, 4.0, 8.0, 16.0, 32.0, 64.0})
    points.push_back({pixels, pixels * lights, a * pixels + b * pixels * lights});
  return points;
}

TEST(TwoTermLimit, RecoversBothTermsOfAnExactLine) {
  const auto fit = fitTwoTerm(exactCurve());
  ASSERT_TRUE(fit);
  EXPECT_NEAR(fit->msPerPixel, 2e-6, 1e-15);
  EXPECT_NEAR(fit->msPerPixelLight, 5e-7, 1e-16);
  EXPECT_LT(fit->rmsRelative, 1e-12);
  EXPECT_LT(fit->maxRelative, 1e-12);
  EXPECT_EQ(fit->points, 7);
  // The estimate of a load the curve never had: 1280x720, 6.5 lights per pixel.
  const double pixels = 1280.0 * 720.0;
  EXPECT_NEAR(fit->estimateMs(pixels, pixels * 6.5), 2e-6 * pixels + 5e-7 * pixels * 6.5, 1e-9);
}

// Two points only: the line through both. Times 1 and 3 ms at 1 and 3
// lights per pixel of one pixel: t = 0 * P + 1 * L.
TEST(TwoTermLimit, TwoPointsAreFittedExactly) {
  const auto fit = fitTwoTerm({{1, 1, 1}, {1, 3, 3}});
  ASSERT_TRUE(fit);
  EXPECT_NEAR(fit->msPerPixel, 0.0, 1e-12);
  EXPECT_NEAR(fit->msPerPixelLight, 1.0, 1e-12);
}

// Three points at L = 1, 2, 3 (P = 1) with times 1, 2.2, 3: the residuals are
// recomputed here from the fitted terms by their definition, and the fit must
// be the weighted optimum (no small change of a term lowers the weighted sum).
TEST(TwoTermLimit, ResidualIsTheRelativeRmsOfTheFit) {
  const std::vector<TwoTermPoint> points = {{1, 1, 1}, {1, 2, 2.2}, {1, 3, 3}};
  const auto fit = fitTwoTerm(points);
  ASSERT_TRUE(fit);
  double sum = 0, largest = 0;
  for (const TwoTermPoint& p : points) {
    const double r = (p.ms - (fit->msPerPixel + fit->msPerPixelLight * p.pixelLights)) / p.ms;
    sum += r * r;
    largest = std::max(largest, std::abs(r));
  }
  EXPECT_NEAR(fit->rmsRelative, std::sqrt(sum / 3), 1e-12);
  EXPECT_NEAR(fit->maxRelative, largest, 1e-12);
  EXPECT_GT(fit->rmsRelative, 0.01);  // 2.2 is 10% off the line through the others
  const auto weighted = [&](double a, double b) {
    double s = 0;
    for (const TwoTermPoint& p : points) s += std::pow((p.ms - a - b * p.pixelLights) / p.ms, 2);
    return s;
  };
  const double best = weighted(fit->msPerPixel, fit->msPerPixelLight);
  for (const double d : {-1e-3, 1e-3}) {
    EXPECT_GE(weighted(fit->msPerPixel + d, fit->msPerPixelLight), best);
    EXPECT_GE(weighted(fit->msPerPixel, fit->msPerPixelLight + d), best);
  }
}

TEST(TwoTermLimit, NoFitWithoutTwoDistinctLoads) {
  EXPECT_FALSE(fitTwoTerm({}));
  EXPECT_FALSE(fitTwoTerm({{100, 400, 2}}));
  EXPECT_FALSE(fitTwoTerm({{100, 400, 2}, {100, 400, 2.1}}));  // the same lights per pixel twice
  EXPECT_FALSE(fitTwoTerm({{100, 400, 2}, {100, 800, 0}}));    // no time
}

}  // namespace
}  // namespace reports
