// bench::compareToIdeal (suite/bench/image_error.h) on hand-made 8x8 images:
// the ideal is 0.5 in R, G and B, every pixel compared unless a test masks
// one out. Expected values are worked out by hand in the comments.
#include "suite/bench/image_error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace {

constexpr int kSize = 8;  // 64 pixels, 192 channel values
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

imaging::Image ideal() {
  imaging::Image image(kSize, kSize, 4);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      for (int c = 0; c < 3; ++c) image.at(x, y, c) = 0.5f;
      image.at(x, y, 3) = 1.0f;  // compared
    }
  return image;
}

// The ideal's RGB as an RGBA image with alpha 1: a perfect render.
imaging::Image perfect() { return ideal(); }

TEST(ImageError, FiniteImageAsBefore) {
  imaging::Image image = perfect();
  image.at(2, 3, 0) = 0.6f;  // one channel off by 0.1
  const bench::ImageError e = bench::compareToIdeal(image, ideal());
  EXPECT_EQ(e.comparedPixels, 64);
  EXPECT_EQ(e.nonFinitePixels, 0);
  EXPECT_NEAR(e.maxAbs, 0.1, 1e-6);
  // sqrt(0.1^2 / 192) = 0.1 / 13.8564 = 0.00721688
  EXPECT_NEAR(e.rmse, 0.00721688, 1e-7);
  // peak 0.5: 20 log10(0.5 / 0.00721688) = 20 log10(69.2820) = 20 x 1.840620 = 36.8124 dB
  EXPECT_NEAR(e.psnrDb, 36.8124, 1e-3);
  EXPECT_DOUBLE_EQ(e.peak, 0.5);
}

TEST(ImageError, ExactMatchIs999Db) {
  const bench::ImageError e = bench::compareToIdeal(perfect(), ideal());
  EXPECT_EQ(e.nonFinitePixels, 0);
  EXPECT_EQ(e.rmse, 0.0);
  EXPECT_EQ(e.maxAbs, 0.0);
  EXPECT_EQ(e.psnrDb, bench::kPsnrOfExactMatch);
  EXPECT_EQ(e.perceptualFail, 0.0);
}

TEST(ImageError, OneNaNPixelBreaksEveryMeasure) {
  imaging::Image image = perfect();
  image.at(1, 1, 1) = kNaN;  // G of one pixel; the other 63 are exact
  const bench::ImageError e = bench::compareToIdeal(image, ideal());
  EXPECT_EQ(e.comparedPixels, 64);
  EXPECT_EQ(e.nonFinitePixels, 1);
  EXPECT_TRUE(std::isinf(e.maxAbs) && e.maxAbs > 0) << e.maxAbs;
  EXPECT_TRUE(std::isnan(e.rmse)) << e.rmse;
  EXPECT_TRUE(std::isnan(e.psnrDb)) << e.psnrDb;  // not 999, the exact match
  // The NaN pixel fails; the others equal the ideal and cannot: 1 / 64.
  EXPECT_DOUBLE_EQ(e.perceptualFail, 1.0 / 64.0);
}

TEST(ImageError, InfinitiesCountAndDontCarePixelsDoNot) {
  imaging::Image reference = ideal();
  reference.at(7, 7, 3) = 0.0f;  // don't care: 63 compared pixels
  imaging::Image image = perfect();
  image.at(7, 7, 0) = kNaN;      // not compared: not counted
  image.at(0, 0, 0) = kInf;
  image.at(5, 2, 2) = -kInf;
  image.at(3, 3, 0) = 0.6f;      // finite and wrong: the measures are broken all the same
  const bench::ImageError e = bench::compareToIdeal(image, reference);
  EXPECT_EQ(e.comparedPixels, 63);
  EXPECT_EQ(e.nonFinitePixels, 2);
  EXPECT_TRUE(std::isinf(e.maxAbs) && e.maxAbs > 0) << e.maxAbs;
  EXPECT_TRUE(std::isnan(e.rmse)) << e.rmse;
  EXPECT_TRUE(std::isnan(e.psnrDb)) << e.psnrDb;
  // The two infinite pixels fail; (3, 3) may or may not: 2/63 to 3/63.
  EXPECT_GE(e.perceptualFail, 2.0 / 63.0);
  EXPECT_LE(e.perceptualFail, 3.0 / 63.0);
}

TEST(ImageError, AReferenceThatIsNotFiniteIsRefused) {
  imaging::Image reference = ideal();
  reference.at(4, 4, 1) = kNaN;
  EXPECT_THROW(bench::compareToIdeal(perfect(), reference), std::runtime_error);
  reference.at(4, 4, 3) = 0.0f;  // the same pixel not compared: fine
  EXPECT_EQ(bench::compareToIdeal(perfect(), reference).nonFinitePixels, 0);
}

}  // namespace
