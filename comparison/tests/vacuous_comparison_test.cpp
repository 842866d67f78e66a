// SPEC 7: a comparison must be able to fail. Frames worked out by hand: 10x10
// pixels of 0.5 with tolerance 0.25 (comparison_fixtures.h) made black, masked
// or lit; the rule's thresholds on counts alone.
#include "comparison/image_comparison.h"
#include "comparison/tests/comparison_fixtures.h"
#include "comparison/vacuous_comparison.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace comparison {
namespace {

using namespace comparison::testing;

void blacken(Images& images, float value) {
  for (int y = 0; y < images.reference.value.height; ++y)
    for (int x = 0; x < images.reference.value.width; ++x) {
      setRgb(images.reference.value, x, y, value, value, value);
      setRgb(images.result, x, y, value, value, value);
    }
}

bool startsWith(const std::string& text, const std::string& prefix) { return text.rfind(prefix, 0) == 0; }

TEST(VacuousComparison, ALitFramePasses) {
  const Images images = uniform(10, 10);
  const Comparison c = compareImages(images.result, images.reference, {});
  EXPECT_EQ(c.litComparedPixels, 100);
  EXPECT_EQ(c.qualityWarning, "");
  EXPECT_EQ(c.verdict, Verdict::Pass);
}

TEST(VacuousComparison, ABlackFrameMatchedIsAQualityWarning) {
  Images images = uniform(10, 10);
  blacken(images, 0.0f);
  const Comparison c = compareImages(images.result, images.reference, {});
  EXPECT_TRUE(c.comparisonPassed);
  EXPECT_EQ(c.comparedPixels, 100);
  EXPECT_EQ(c.litComparedPixels, 0);
  EXPECT_EQ(c.verdict, Verdict::QualityWarning);
  EXPECT_TRUE(startsWith(c.qualityWarning, "no compared pixel of the reference is above the flush-to-zero floor"))
      << c.qualityWarning;
}

TEST(VacuousComparison, ValuesAtTheFlushToZeroFloorAreStillBlack) {
  Images images = uniform(10, 10);
  blacken(images, std::ldexp(1.0f, -126));  // equal to the floor, not above it
  EXPECT_EQ(compareImages(images.result, images.reference, {}).verdict, Verdict::QualityWarning);
  blacken(images, std::ldexp(1.0f, -125));  // above it: something to check
  EXPECT_EQ(compareImages(images.result, images.reference, {}).verdict, Verdict::Pass);
}

TEST(VacuousComparison, ABlackFrameTheBackendLitStillFails) {
  Images images = uniform(10, 10);
  blacken(images, 0.0f);
  setRgb(images.result, 3, 4, 1.0f, 1.0f, 1.0f);  // 1 against 0, tolerance 0.25
  const Comparison c = compareImages(images.result, images.reference, {});
  EXPECT_EQ(c.verdict, Verdict::Fail);
  EXPECT_FALSE(c.qualityWarning.empty());  // said, though the Fail is what counts
}

TEST(VacuousComparison, AnAllMaskedFrameIsAQualityWarning) {
  Images images = uniform(10, 10);
  for (int y = 0; y < 10; ++y)
    for (int x = 0; x < 10; ++x) mask(images, x, y);
  const Comparison c = compareImages(images.result, images.reference, {});
  EXPECT_EQ(c.comparedPixels, 0);
  EXPECT_EQ(c.verdict, Verdict::QualityWarning);
  EXPECT_TRUE(startsWith(c.qualityWarning, "only 0 of 100 pixels are compared")) << c.qualityWarning;
}

TEST(VacuousComparison, OneComparedPixelInAHundredIsEnough) {
  Images images = uniform(10, 10);
  for (int y = 0; y < 10; ++y)
    for (int x = 0; x < 10; ++x)
      if (x != 5 || y != 5) mask(images, x, y);
  const Comparison c = compareImages(images.result, images.reference, {});
  EXPECT_EQ(c.comparedPixels, 1);
  EXPECT_EQ(c.verdict, Verdict::Pass);  // 1% is the documented minimum share
}

TEST(VacuousComparison, TheRuleOnCounts) {
  EXPECT_EQ(vacuousComparisonReason({1000, 10, 10}), "");
  EXPECT_TRUE(startsWith(vacuousComparisonReason({1000, 9, 9}), "only 9 of 1000 pixels are compared (0.90%"));
  EXPECT_TRUE(startsWith(vacuousComparisonReason({1000, 1000, 0}), "no compared pixel"));
  EXPECT_NE(vacuousComparisonReason({1000, 0, 0}).find("only 0 of 1000"), std::string::npos);
  EXPECT_EQ(vacuousComparisonReason({1000, 1000, 1}), "");
}

}  // namespace
}  // namespace comparison
