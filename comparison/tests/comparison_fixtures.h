// Tiny hand-built images for the comparison tests: values and tolerances are
// binary fractions, so every difference and bound below is exact.
#pragma once

#include "reference/reference_renderer.h"

namespace comparison::testing {

constexpr float kValue = 0.5f;
constexpr float kTolerance = 0.25f;

// A reference of kValue everywhere, all compared, kTolerance in every channel,
// and a result equal to it.
struct Images {
  imaging::Image result;
  reference::ReferenceImages reference;
};

inline Images uniform(int width, int height, int resultChannels = 3) {
  Images images;
  images.result = imaging::Image(width, height, resultChannels);
  images.reference.value = imaging::Image(width, height, 4);
  images.reference.tolerance = imaging::Image(width, height, 3);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      for (int c = 0; c < 3; ++c) {
        images.result.at(x, y, c) = kValue;
        images.reference.value.at(x, y, c) = kValue;
        images.reference.tolerance.at(x, y, c) = kTolerance;
      }
      if (resultChannels == 4) images.result.at(x, y, 3) = 1;
      images.reference.value.at(x, y, 3) = 1;
    }
  return images;
}

inline void setRgb(imaging::Image& image, int x, int y, float r, float g, float b) {
  image.at(x, y, 0) = r;
  image.at(x, y, 1) = g;
  image.at(x, y, 2) = b;
}

inline void mask(Images& images, int x, int y) {
  images.reference.value.at(x, y, 3) = 0;
  ++images.reference.maskedPixels;
}

}  // namespace comparison::testing
