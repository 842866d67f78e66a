// The error of a rendered image against the `--ideal` reference (SPEC 6):
// the err_* counters of the frame benchmarks (docs/bench-format.md).
#pragma once

#include "imaging/image.h"

#include <cstdint>

namespace bench {

// OpenImageIO's perceptual comparison (Hector Yee's metric) needs the
// viewing conditions: an office monitor of 100 cd/m^2 seen under a 45 degree
// field of view (OpenImageIO's defaults; `oiiotool --pdiff` uses the same).
constexpr float kPerceptualLuminance = 100.0f;  // cd/m^2, adaptation luminance
constexpr float kPerceptualFovDeg = 45.0f;      // horizontal field of view of the display

// err_psnr_db when the image equals the reference exactly (an infinite PSNR
// has no JSON spelling).
constexpr double kPsnrOfExactMatch = 999.0;

// A compared pixel with a NaN or infinite R, G or B is broken: no error
// measures it. Where any is, maxAbs is +infinity and rmse and psnrDb are NaN
// (JSON null: docs/bench-format.md), never a number a front could rank.
struct ImageError {
  double rmse = 0;     // sqrt(mean of (image - ideal)^2) over R, G, B of compared pixels
  double maxAbs = 0;   // max |image - ideal| over R, G, B of compared pixels
  double peak = 0;     // max of the ideal image's R, G, B over compared pixels: PSNR's peak
  double psnrDb = 0;   // 20 log10(peak / rmse)
  // Pixels compare_Yee finds different, over compared pixels. Pixels the
  // mask leaves out are given the ideal value first, so they cannot fail
  // (the metric is spatial: their neighbours see the ideal values there);
  // so are non-finite pixels, which then count as failing.
  double perceptualFail = 0;
  std::int64_t comparedPixels = 0;
  std::int64_t nonFinitePixels = 0;  // compared pixels with a non-finite R, G or B
};

// `image`: RGB(A) float, row 0 at the top (Backend::readback). `ideal`: the
// reference's value image, RGB value and A mask (1 compared, 0 don't care).
// Throws std::invalid_argument when the sizes differ, std::runtime_error when
// a compared pixel of the reference is not finite (no error can be measured).
ImageError compareToIdeal(const imaging::Image& image, const imaging::Image& ideal);

}  // namespace bench
