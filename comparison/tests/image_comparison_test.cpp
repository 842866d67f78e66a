// compareImages on tiny images whose expected counts and metrics are worked
// out by hand: 4x3 pixels of 0.5 with tolerance 0.25 unless a test says else.
#include "comparison/image_comparison.h"
#include "comparison/tests/comparison_fixtures.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace comparison {
namespace {

using namespace comparison::testing;

constexpr double kInf = std::numeric_limits<double>::infinity();

void expectRgb(const imaging::Image& image, int x, int y, float r, float g, float b) {
  EXPECT_EQ(image.at(x, y, 0), r) << "at (" << x << ", " << y << ")";
  EXPECT_EQ(image.at(x, y, 1), g) << "at (" << x << ", " << y << ")";
  EXPECT_EQ(image.at(x, y, 2), b) << "at (" << x << ", " << y << ")";
}

TEST(CompareImages, EqualImagesPass) {
  const Images images = uniform(4, 3);
  const Comparison c = compareImages(images.result, images.reference, {});
  EXPECT_EQ(c.width, 4);
  EXPECT_EQ(c.height, 3);
  EXPECT_EQ(c.comparedPixels, 12);
  EXPECT_EQ(c.maskedPixels, 0);
  EXPECT_EQ(c.failingPixels, 0);
  EXPECT_EQ(c.nonFinitePixels, 0);
  EXPECT_EQ(c.maxAbsError, 0);
  EXPECT_EQ(c.maxErrorOverTolerance, 0);
  EXPECT_EQ(c.rmse, 0);
  EXPECT_TRUE(c.worst.empty());
  EXPECT_TRUE(c.comparisonPassed);
  EXPECT_FALSE(c.expectFail);
  EXPECT_EQ(c.verdict, Verdict::Pass);
  ASSERT_EQ(c.errorMask.channels, 3);
  for (float v : c.errorMask.pixels) EXPECT_EQ(v, 0.0f);
}

TEST(CompareImages, OnePixelBeyondToleranceFails) {
  Images images = uniform(4, 3);
  images.result.at(2, 1, 0) = 1.0f;  // |1 - 0.5| = 0.5: 0.25 over the tolerance, twice it
  const Comparison c = compareImages(images.result, images.reference, {});
  EXPECT_EQ(c.failingPixels, 1);
  EXPECT_EQ(c.comparedPixels, 12);
  EXPECT_FALSE(c.comparisonPassed);
  EXPECT_EQ(c.verdict, Verdict::Fail);
  EXPECT_EQ(c.maxAbsError, 0.5);
  EXPECT_EQ(c.maxErrorOverTolerance, 2.0);
  // One difference of 0.5 among 12 pixels x 3 channels.
  EXPECT_DOUBLE_EQ(c.rmse, std::sqrt(0.25 / 36));
  ASSERT_EQ(c.worst.size(), 1u);
  const PixelReport& p = c.worst[0];
  EXPECT_EQ(p.x, 2);
  EXPECT_EQ(p.y, 1);
  EXPECT_EQ(p.excess, 0.25);
  EXPECT_FALSE(p.nonFinite);
  EXPECT_EQ(p.result[0], 1.0f);
  EXPECT_EQ(p.result[1], kValue);
  EXPECT_EQ(p.reference[0], kValue);
  EXPECT_EQ(p.tolerance[0], kTolerance);
  expectRgb(c.errorMask, 2, 1, 1, 0, 0);
  expectRgb(c.errorMask, 1, 1, 0, 0, 0);
}

TEST(CompareImages, DifferenceOfExactlyTheTolerancePasses) {
  Images images = uniform(4, 3);
  setRgb(images.result, 0, 0, 0.75f, 0.25f, 0.75f);  // every channel off by exactly 0.25
  const Comparison c = compareImages(images.result, images.reference, {});
  EXPECT_EQ(c.failingPixels, 0);
  EXPECT_EQ(c.verdict, Verdict::Pass);
  EXPECT_EQ(c.maxAbsError, 0.25);
  EXPECT_EQ(c.maxErrorOverTolerance, 1.0);
}

TEST(CompareImages, MaskedPixelIsNotComparedButCounted) {
  Images images = uniform(4, 3);
  mask(images, 0, 0);
  setRgb(images.result, 0, 0, 1000, -1000, 1000);
  const Comparison c = compareImages(images.result, images.reference, {});
  EXPECT_EQ(c.failingPixels, 0);
  EXPECT_EQ(c.maskedPixels, 1);
  EXPECT_EQ(c.comparedPixels, 11);
  EXPECT_EQ(c.maxAbsError, 0);  // metrics cover compared pixels only
  EXPECT_EQ(c.verdict, Verdict::Pass);
  expectRgb(c.errorMask, 0, 0, 0.25f, 0.25f, 0.25f);
}

TEST(CompareImages, NanFailsEvenWhereMasked) {
  Images images = uniform(4, 3);
  mask(images, 1, 1);
  images.result.at(1, 1, 1) = std::numeric_limits<float>::quiet_NaN();
  lighting::Expectation expect;
  expect.maxFailingPixels = 5;  // a non-finite pixel fails the scene whatever the allowance
  const Comparison c = compareImages(images.result, images.reference, expect);
  EXPECT_EQ(c.maskedPixels, 1);
  EXPECT_EQ(c.failingPixels, 1);
  EXPECT_EQ(c.nonFinitePixels, 1);
  EXPECT_FALSE(c.comparisonPassed);
  EXPECT_EQ(c.verdict, Verdict::Fail);
  ASSERT_EQ(c.worst.size(), 1u);
  EXPECT_TRUE(c.worst[0].nonFinite);
  EXPECT_EQ(c.worst[0].excess, kInf);
  EXPECT_EQ(c.maxAbsError, 0);
  expectRgb(c.errorMask, 1, 1, 1, 0, 1);
}

TEST(CompareImages, InfinityInRgbFailsAndLeavesMetricsFinite) {
  Images images = uniform(4, 3);
  images.result.at(3, 2, 2) = -std::numeric_limits<float>::infinity();
  const Comparison c = compareImages(images.result, images.reference, {});
  EXPECT_EQ(c.failingPixels, 1);
  EXPECT_EQ(c.nonFinitePixels, 1);
  EXPECT_EQ(c.verdict, Verdict::Fail);
  EXPECT_EQ(c.maxAbsError, 0);
  EXPECT_EQ(c.maxErrorOverTolerance, 0);
  EXPECT_EQ(c.rmse, 0);
  expectRgb(c.errorMask, 3, 2, 1, 0, 1);
}

TEST(CompareImages, InfinityInAlphaFails) {
  Images images = uniform(4, 3, 4);
  images.result.at(0, 2, 3) = std::numeric_limits<float>::infinity();
  const Comparison c = compareImages(images.result, images.reference, {});
  EXPECT_EQ(c.failingPixels, 1);
  EXPECT_EQ(c.nonFinitePixels, 1);
  EXPECT_EQ(c.verdict, Verdict::Fail);
  ASSERT_EQ(c.worst.size(), 1u);
  EXPECT_EQ(c.worst[0].x, 0);
  EXPECT_EQ(c.worst[0].y, 2);
}

TEST(CompareImages, NanInTheReferenceOrToleranceFails) {
  Images images = uniform(4, 3);
  images.reference.value.at(1, 0, 2) = std::numeric_limits<float>::quiet_NaN();
  images.reference.tolerance.at(2, 0, 0) = std::numeric_limits<float>::quiet_NaN();
  const Comparison c = compareImages(images.result, images.reference, {});
  EXPECT_EQ(c.failingPixels, 2);
  EXPECT_EQ(c.nonFinitePixels, 0);  // that counts the result's values only
  ASSERT_EQ(c.worst.size(), 2u);
  EXPECT_EQ(c.worst[0].x, 1);
  EXPECT_EQ(c.worst[0].excess, kInf);
  EXPECT_EQ(c.worst[1].x, 2);
  EXPECT_EQ(c.worst[1].excess, kInf);
}

TEST(CompareImages, MaxFailingPixelsAllowsThatMany) {
  Images images = uniform(4, 3);
  images.result.at(0, 0, 0) = 1.0f;
  lighting::Expectation expect;
  expect.maxFailingPixels = 1;
  Comparison c = compareImages(images.result, images.reference, expect);
  EXPECT_EQ(c.failingPixels, 1);
  EXPECT_TRUE(c.comparisonPassed);
  EXPECT_EQ(c.verdict, Verdict::Pass);
  EXPECT_EQ(c.maxFailingPixels, 1);

  images.result.at(1, 0, 0) = 1.0f;
  c = compareImages(images.result, images.reference, expect);
  EXPECT_EQ(c.failingPixels, 2);
  EXPECT_EQ(c.verdict, Verdict::Fail);
}

TEST(CompareImages, ToleranceScaleMultipliesTheBound) {
  Images images = uniform(4, 3);
  images.result.at(0, 0, 0) = 1.0f;   // off by 0.5: exactly 2 x 0.25
  images.result.at(1, 0, 0) = 1.25f;  // off by 0.75: 0.25 over 2 x 0.25
  lighting::Expectation expect;
  expect.toleranceScale = 2;
  const Comparison c = compareImages(images.result, images.reference, expect);
  EXPECT_EQ(c.failingPixels, 1);
  ASSERT_EQ(c.worst.size(), 1u);
  EXPECT_EQ(c.worst[0].x, 1);
  EXPECT_EQ(c.worst[0].excess, 0.25);
  EXPECT_EQ(c.worst[0].tolerance[0], kTolerance);  // reported as in the reference, unscaled
  EXPECT_EQ(c.maxErrorOverTolerance, 1.5);
  EXPECT_EQ(c.toleranceScale, 2);
}

TEST(CompareImages, ExpectFailPassesOnlyWhenTheMismatchIsDetected) {
  Images images = uniform(4, 3);
  lighting::Expectation expect;
  expect.expectFail = true;

  Comparison c = compareImages(images.result, images.reference, expect);
  EXPECT_TRUE(c.comparisonPassed);
  EXPECT_TRUE(c.expectFail);
  EXPECT_EQ(c.verdict, Verdict::Fail);  // the mismatch went undetected

  images.result.at(2, 2, 1) = 0.0f;
  c = compareImages(images.result, images.reference, expect);
  EXPECT_FALSE(c.comparisonPassed);
  EXPECT_EQ(c.failingPixels, 1);
  EXPECT_EQ(c.verdict, Verdict::Pass);
}

TEST(CompareImages, ExpectFailDoesNotExcuseNonFiniteValues) {
  Images images = uniform(4, 3);
  images.result.at(0, 1, 0) = std::numeric_limits<float>::quiet_NaN();
  lighting::Expectation expect;
  expect.expectFail = true;
  const Comparison c = compareImages(images.result, images.reference, expect);
  EXPECT_FALSE(c.comparisonPassed);
  EXPECT_EQ(c.verdict, Verdict::Fail);
}

TEST(CompareImages, WorstAreLargestExcessFirstThenRowThenColumn) {
  Images images = uniform(4, 3);
  images.result.at(3, 0, 0) = 1.0f;   // excess 0.25
  images.result.at(0, 2, 1) = 1.5f;   // excess 0.75
  images.result.at(3, 1, 2) = -0.5f;  // excess 0.75
  images.result.at(1, 1, 0) = 1.5f;   // excess 0.75
  images.result.at(2, 2, 0) = 1.25f;  // excess 0.5
  const Comparison c = compareImages(images.result, images.reference, {}, 4);
  EXPECT_EQ(c.failingPixels, 5);
  ASSERT_EQ(c.worst.size(), 4u);
  const int expected[4][2] = {{1, 1}, {3, 1}, {0, 2}, {2, 2}};
  const double excess[4] = {0.75, 0.75, 0.75, 0.5};
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(c.worst[i].x, expected[i][0]) << "worst[" << i << "]";
    EXPECT_EQ(c.worst[i].y, expected[i][1]) << "worst[" << i << "]";
    EXPECT_EQ(c.worst[i].excess, excess[i]) << "worst[" << i << "]";
  }
}

TEST(CompareImages, WorstCountZeroListsNone) {
  Images images = uniform(4, 3);
  images.result.at(0, 0, 0) = 1.0f;
  const Comparison c = compareImages(images.result, images.reference, {}, 0);
  EXPECT_EQ(c.failingPixels, 1);
  EXPECT_TRUE(c.worst.empty());
}

TEST(CompareImages, TightnessIsTheLargestErrorOverTolerance) {
  Images images = uniform(4, 3);
  images.reference.tolerance.at(1, 0, 2) = 0.5f;
  images.result.at(1, 0, 2) = 0.75f;  // 0.25 of 0.5
  images.result.at(2, 0, 0) = 0.625f;  // 0.125 of 0.25
  Comparison c = compareImages(images.result, images.reference, {});
  EXPECT_EQ(c.failingPixels, 0);
  EXPECT_EQ(c.maxAbsError, 0.25);
  EXPECT_EQ(c.maxErrorOverTolerance, 0.5);

  // A zero tolerance with no difference adds nothing; with any difference it is infinitely tight.
  images.reference.tolerance.at(3, 2, 1) = 0;
  c = compareImages(images.result, images.reference, {});
  EXPECT_EQ(c.maxErrorOverTolerance, 0.5);
  images.result.at(3, 2, 1) = 0.5f + 0x1p-24f;
  c = compareImages(images.result, images.reference, {});
  EXPECT_EQ(c.maxErrorOverTolerance, kInf);
  EXPECT_EQ(c.failingPixels, 1);
}

TEST(CompareImages, MismatchedImagesThrow) {
  const Images images = uniform(4, 3);
  const Images other = uniform(3, 3);
  EXPECT_THROW(compareImages(other.result, images.reference, {}), std::invalid_argument);

  reference::ReferenceImages reference = images.reference;
  reference.tolerance = other.reference.tolerance;
  EXPECT_THROW(compareImages(images.result, reference, {}), std::invalid_argument);

  EXPECT_THROW(compareImages(imaging::Image(4, 3, 2), images.reference, {}), std::invalid_argument);
  reference = images.reference;
  reference.value = imaging::Image(4, 3, 3);
  EXPECT_THROW(compareImages(images.result, reference, {}), std::invalid_argument);

  EXPECT_THROW(compareImages(images.result, images.reference, {}, -1), std::invalid_argument);
}

TEST(CompareImages, SizeMismatchMessageNamesTheSizes) {
  const Images images = uniform(4, 3);
  try {
    compareImages(uniform(3, 3).result, images.reference, {});
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("result 3x3, reference 4x3"), std::string::npos) << e.what();
  }
}


// SPEC 3.9's cap: more than 5% of the shadowed pixels ambiguous makes the
// scene defective, a Fail whatever the pixels say; 5% exactly is allowed.
TEST(CompareImages, ShadowAmbiguityOverTheCapIsADefectiveScene) {
  Images images = uniform(4, 3);
  images.reference.shadowedPixels = 100;
  images.reference.ambiguousShadowPixels = 5;
  Comparison c = compareImages(images.result, images.reference, {});
  EXPECT_FALSE(c.defectiveScene);
  EXPECT_EQ(c.verdict, Verdict::Pass);
  images.reference.ambiguousShadowPixels = 6;
  c = compareImages(images.result, images.reference, {});
  EXPECT_TRUE(c.defectiveScene);
  EXPECT_TRUE(c.comparisonPassed);  // every pixel agrees, and still:
  EXPECT_EQ(c.verdict, Verdict::Fail);
  EXPECT_EQ(c.shadowedPixels, 100);
  EXPECT_EQ(c.ambiguousShadowPixels, 6);
}

// A failing pixel carries its shadow interval when the reference kept them.
TEST(CompareImages, FailingPixelsCarryTheirShadowInterval) {
  Images images = uniform(4, 3);
  images.reference.shadowInterval = imaging::Image(4, 3, 3);
  images.reference.shadowInterval.at(2, 1, 0) = 0.25f;
  images.reference.shadowInterval.at(2, 1, 1) = 0.75f;
  images.reference.shadowInterval.at(2, 1, 2) = 1.0f;
  images.result.at(2, 1, 0) = 1.0f;  // 0.5 off, tolerance 0.25
  images.result.at(1, 1, 0) = 1.0f;  // not shadowed
  const Comparison c = compareImages(images.result, images.reference, {});
  ASSERT_EQ(c.worst.size(), 2u);
  const PixelReport& shadowed = c.worst[0].x == 2 ? c.worst[0] : c.worst[1];
  const PixelReport& plain = c.worst[0].x == 2 ? c.worst[1] : c.worst[0];
  EXPECT_TRUE(shadowed.shadowed);
  EXPECT_EQ(shadowed.shadowLo, 0.25f);
  EXPECT_EQ(shadowed.shadowHi, 0.75f);
  EXPECT_FALSE(plain.shadowed);
}

}  // namespace
}  // namespace comparison
