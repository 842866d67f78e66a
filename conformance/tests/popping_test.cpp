#include "conformance/popping.h"

#include <gtest/gtest.h>

#include <cmath>

namespace conformance {
namespace {

// A 2x1 reference: pixel 0 compared, pixel 1 masked.
reference::ReferenceImages ideal(float r0, float r1) {
  reference::ReferenceImages images;
  images.value = imaging::Image(2, 1, 4);
  images.value.at(0, 0, 0) = r0;
  images.value.at(0, 0, 3) = 1;
  images.value.at(1, 0, 0) = r1;
  images.value.at(1, 0, 3) = 0;
  return images;
}

imaging::Image result(float r0, float r1) {
  imaging::Image image(2, 1, 4);
  image.at(0, 0, 0) = r0;
  image.at(1, 0, 0) = r1;
  return image;
}

TEST(Popping, ErrorAgainstIdealSkipsMaskedPixels) {
  double maxError = -1;
  const imaging::Image e = idealError(result(0.75f, 100), ideal(1.0f, 0), maxError);
  EXPECT_FLOAT_EQ(e.at(0, 0, 0), -0.25f);
  EXPECT_TRUE(std::isnan(e.at(1, 0, 0)));  // masked: the 100 does not count
  EXPECT_DOUBLE_EQ(maxError, 0.25);
}

TEST(Popping, JumpIsTheLargestChangeOfTheError) {
  double unused = 0;
  // Frame 0: the backend drops a light worth 0.5 (e = -0.5); frame 1 keeps it (e = 0).
  const imaging::Image e0 = idealError(result(1.0f, 0), ideal(1.5f, 0), unused);
  const imaging::Image e1 = idealError(result(2.0f, 7), ideal(2.0f, 0), unused);
  EXPECT_DOUBLE_EQ(poppingJump(e0, e1), 0.5);
  EXPECT_DOUBLE_EQ(poppingJump(e1, e1), 0.0);
}

TEST(Popping, FramesOfDifferentSizesAreRejected) {
  EXPECT_THROW(poppingJump(imaging::Image(2, 1, 3), imaging::Image(1, 1, 3)), std::invalid_argument);
}

}  // namespace
}  // namespace conformance
