// The Mann-Whitney U test against values worked out by hand.
#include "reports/bench_stats.h"

#include <gtest/gtest.h>

#include <cmath>

namespace reports {
namespace {

TEST(BenchMannWhitney, SeparatedThreeAgainstThree) {
  // Ranks of 1,2,3 are 1,2,3: R1 = 6, U1 = 6 - 3*4/2 = 0. Of the C(6,3) = 20
  // equally likely rank sets only {1,2,3} and {4,5,6} are as extreme: p = 2/20.
  const MannWhitney t = mannWhitneyU({1, 2, 3}, {4, 5, 6});
  EXPECT_DOUBLE_EQ(t.u1, 0);
  EXPECT_DOUBLE_EQ(t.u, 0);
  EXPECT_TRUE(t.exact);
  EXPECT_FALSE(t.ties);
  EXPECT_NEAR(t.p, 0.1, 1e-12);
  const MannWhitney reversed = mannWhitneyU({6, 5, 4}, {3, 2, 1});
  EXPECT_DOUBLE_EQ(reversed.u1, 9);
  EXPECT_DOUBLE_EQ(reversed.u, 0);
  EXPECT_NEAR(reversed.p, 0.1, 1e-12);
}

TEST(BenchMannWhitney, FiveAgainstFiveSmallestP) {
  // C(10,5) = 252: the smallest two-sided p is 2/252 = 0.0079.
  const MannWhitney t = mannWhitneyU({10.1, 10.3, 10.2, 10.0, 10.4}, {11, 11.2, 11.1, 11.3, 11.4});
  EXPECT_NEAR(t.p, 2.0 / 252, 1e-12);
  EXPECT_LT(t.p, 0.05);
  // One overlap: U = 1; sums at least as far from the mean: U in {0, 1, 24, 25},
  // counts 1 + 1 + 1 + 1 -> p = 4/252.
  const MannWhitney overlap = mannWhitneyU({1, 2, 3, 4, 6}, {5, 7, 8, 9, 10});
  EXPECT_DOUBLE_EQ(overlap.u, 1);
  EXPECT_NEAR(overlap.p, 4.0 / 252, 1e-12);
}

TEST(BenchMannWhitney, TiesExact) {
  // Pooled 1,2,2,2,3,4 -> midranks 1,3,3,3,5,6. R1 = 1+3+3 = 7, U1 = 7 - 6 = 1,
  // U2 = 8, U = 1. E[R1] = 3*7/2 = 10.5, |7 - 10.5| = 3.5. Of the 20 rank sets,
  // sums 7 ({1,3,3} three ways) and 14 ({3,5,6} three ways) are as extreme:
  // p = 6/20 = 0.3.
  const MannWhitney t = mannWhitneyU({1, 2, 2}, {2, 3, 4});
  EXPECT_DOUBLE_EQ(t.u1, 1);
  EXPECT_DOUBLE_EQ(t.u, 1);
  EXPECT_TRUE(t.ties);
  EXPECT_TRUE(t.exact);
  EXPECT_NEAR(t.p, 0.3, 1e-12);
}

TEST(BenchMannWhitney, TiesNormalApproximation) {
  // Forced to the normal approximation: one tie group of 3, sum(t^3 - t) = 24,
  // sigma^2 = 3*3/12 * (7 - 24/(6*5)) = 4.65, z = (3.5 - 0.5)/sqrt(4.65) = 1.39122,
  // p = erfc(z/sqrt 2) = 0.164160.
  const MannWhitney t = mannWhitneyU({1, 2, 2}, {2, 3, 4}, 0);
  EXPECT_FALSE(t.exact);
  EXPECT_NEAR(t.p, 0.164160, 1e-6);
}

TEST(BenchMannWhitney, LargerSamples) {
  std::vector<double> low, high;
  for (int i = 1; i <= 10; ++i) low.push_back(i), high.push_back(10 + i);
  // Exact: C(20,10) = 184756 arrangements, two as extreme.
  const MannWhitney exact = mannWhitneyU(low, high);
  EXPECT_TRUE(exact.exact);
  EXPECT_NEAR(exact.p, 2.0 / 184756, 1e-15);
  // Normal: mu = 50, sigma^2 = 10*10*21/12 = 175, z = 49.5/sqrt(175) = 3.74185, p = 1.82672e-4.
  const MannWhitney normal = mannWhitneyU(low, high, 1000);
  EXPECT_FALSE(normal.exact);
  EXPECT_NEAR(normal.p, 1.82672e-4, 1e-9);
}

TEST(BenchMannWhitney, DegenerateSamples) {
  EXPECT_DOUBLE_EQ(mannWhitneyU({}, {1, 2}).p, 1);
  EXPECT_DOUBLE_EQ(mannWhitneyU({2, 2, 2}, {2, 2}).p, 1);
  EXPECT_DOUBLE_EQ(mannWhitneyU({1, 2, 3}, {1, 2, 3}).p, 1);
}

}  // namespace
}  // namespace reports
