#include "suite/bench/image_error.h"

#include "imaging/image_codec_loader.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace bench {

ImageError compareToIdeal(const imaging::Image& image, const imaging::Image& ideal) {
  if (image.width != ideal.width || image.height != ideal.height || image.channels < 3 || ideal.channels < 4)
    throw std::invalid_argument("compareToIdeal: image and reference differ in size or channels");
  const int w = ideal.width, h = ideal.height;
  ImageError error;
  double sumSquares = 0;
  // RGB copies for the perceptual metric: the reference, and the image with the
  // don't-care pixels replaced by the reference.
  std::vector<float> a(std::size_t(w) * h * 3), b(a.size());
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const bool compared = ideal.at(x, y, 3) > 0.5f;
      const std::size_t k = (std::size_t(y) * w + x) * 3;
      bool finite = true;
      for (int c = 0; c < 3; ++c) {
        const float want = ideal.at(x, y, c);
        if (compared && !std::isfinite(want))
          throw std::runtime_error("compareToIdeal: the reference has a non-finite value at a compared pixel");
        finite = finite && std::isfinite(image.at(x, y, c));
        a[k + c] = want;
      }
      // A non-finite pixel gets the ideal value for compare_Yee (it would
      // spread to its neighbours) and is counted as failing below.
      for (int c = 0; c < 3; ++c) b[k + c] = compared && finite ? image.at(x, y, c) : a[k + c];
      if (!compared) continue;
      ++error.comparedPixels;
      if (!finite) ++error.nonFinitePixels;
      for (int c = 0; c < 3; ++c) {
        const double want = a[k + c], d = finite ? double(image.at(x, y, c)) - want : 0.0;
        sumSquares += d * d;
        error.maxAbs = std::max(error.maxAbs, std::abs(d));
        error.peak = std::max(error.peak, want);
      }
    }
  }
  if (error.comparedPixels == 0) return error;
  if (error.nonFinitePixels > 0) {
    error.maxAbs = std::numeric_limits<double>::infinity();
    error.rmse = error.psnrDb = std::numeric_limits<double>::quiet_NaN();
  } else {
    error.rmse = std::sqrt(sumSquares / (3.0 * double(error.comparedPixels)));
    error.psnrDb = error.rmse > 0 && error.peak > 0 ? 20.0 * std::log10(error.peak / error.rmse) : kPsnrOfExactMatch;
  }

  std::string why;
  const long failing = imaging::imageCodec().perceptualDifferences(a.data(), b.data(), w, h, kPerceptualLuminance,
                                                                   kPerceptualFovDeg, why);
  if (failing < 0) throw std::runtime_error("OpenImageIO compare_Yee failed: " + why);
  error.perceptualFail = double(failing + error.nonFinitePixels) / double(error.comparedPixels);
  return error;
}

}  // namespace bench
