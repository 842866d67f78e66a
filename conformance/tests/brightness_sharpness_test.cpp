#include "conformance/brightness_sharpness.h"

#include <gtest/gtest.h>

#include <cmath>

namespace conformance {
namespace {

// A 3x1 frame drawn exactly: values v, tolerances t, light parts l; pixel 2
// is masked, so its light part (the largest relative to its tolerance)
// never counts.
struct Frame {
  reference::ReferenceImages reference;
  imaging::Image result{3, 1, 4};
  imaging::Image lightPart{3, 1, 3};
};

Frame frame() {
  const float v[3] = {1.0f, 2.0f, 4.0f}, t[3] = {0.01f, 0.1f, 1e-6f}, l[3] = {0.5f, 2.0f, 4.0f};
  Frame f;
  f.reference.value = imaging::Image(3, 1, 4);
  f.reference.tolerance = imaging::Image(3, 1, 3);
  for (int i = 0; i < 3; ++i) {
    for (int c = 0; c < 3; ++c) {
      f.reference.value.at(i, 0, c) = v[i];
      f.reference.tolerance.at(i, 0, c) = t[i];
      f.result.at(i, 0, c) = v[i];
      f.lightPart.at(i, 0, c) = l[i];
    }
    f.reference.value.at(i, 0, 3) = i == 2 ? 0.0f : 1.0f;
    f.result.at(i, 0, 3) = 1.0f;
  }
  return f;
}

TEST(BrightnessSharpness, TheSmallestCaughtErrorIsTheTightestPixelsToleranceOverItsLightPart) {
  const Frame f = frame();
  // Pixel 0 fails once e * 0.5 > 0.01 (e > 0.02), pixel 1 once e * 2 > 0.1
  // (e > 0.05): the first to fail decides, each way.
  const CaughtScale caught = smallestCaughtScale(f.result, f.lightPart, f.reference, lighting::Expectation{});
  EXPECT_NEAR(caught.brighter, 0.02, 0.02 * 2 * kSharpnessPrecision);
  EXPECT_NEAR(caught.darker, 0.02, 0.02 * 2 * kSharpnessPrecision);
}

TEST(BrightnessSharpness, AnErrorNoPixelCanShowIsNeverCaught) {
  Frame f = frame();
  for (int i = 0; i < 3; ++i)
    for (int c = 0; c < 3; ++c) f.lightPart.at(i, 0, c) = 0.0f;  // no light reaches the frame
  const CaughtScale caught = smallestCaughtScale(f.result, f.lightPart, f.reference, lighting::Expectation{});
  EXPECT_TRUE(std::isinf(caught.brighter));
  EXPECT_TRUE(std::isinf(caught.darker));
}

TEST(BrightnessSharpness, AFrameThatFailsAlreadyCatchesEveryError) {
  Frame f = frame();
  f.result.at(0, 0, 0) = 1.5f;
  const CaughtScale caught = smallestCaughtScale(f.result, f.lightPart, f.reference, lighting::Expectation{});
  EXPECT_EQ(caught.brighter, 0.0);
  EXPECT_EQ(caught.darker, 0.0);
}

}  // namespace
}  // namespace conformance
