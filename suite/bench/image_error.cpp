#include "suite/bench/image_error.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace bench {

ImageError compareToIdeal(const imaging::Image& image, const imaging::Image& ideal) {
  if (image.width != ideal.width || image.height != ideal.height || image.channels < 3 || ideal.channels < 4)
    throw std::invalid_argument("compareToIdeal: image and reference differ in size or channels");
  const int w = ideal.width, h = ideal.height;
  ImageError error;
  double sumSquares = 0;
  // RGB copies for OpenImageIO: the reference, and the image with the
  // don't-care pixels replaced by the reference.
  std::vector<float> a(std::size_t(w) * h * 3), b(a.size());
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const bool compared = ideal.at(x, y, 3) > 0.5f;
      const std::size_t k = (std::size_t(y) * w + x) * 3;
      for (int c = 0; c < 3; ++c) {
        const double want = ideal.at(x, y, c), got = image.at(x, y, c);
        a[k + c] = float(want);
        b[k + c] = compared ? float(got) : float(want);
        if (!compared) continue;
        const double d = got - want;
        sumSquares += d * d;
        error.maxAbs = std::max(error.maxAbs, std::abs(d));
        error.peak = std::max(error.peak, want);
      }
      error.comparedPixels += compared ? 1 : 0;
    }
  }
  if (error.comparedPixels == 0) return error;
  error.rmse = std::sqrt(sumSquares / (3.0 * double(error.comparedPixels)));
  error.psnrDb = error.rmse > 0 && error.peak > 0 ? 20.0 * std::log10(error.peak / error.rmse) : kPsnrOfExactMatch;

  const OIIO::ImageSpec spec(w, h, 3, OIIO::TypeDesc::FLOAT);
  const OIIO::ImageBuf bufA(spec, a.data()), bufB(spec, b.data());
  OIIO::ImageBufAlgo::CompareResults result{};  // compare_Yee fills maxerror and the worst pixel only
  const int failing =
      OIIO::ImageBufAlgo::compare_Yee(bufA, bufB, result, kPerceptualLuminance, kPerceptualFovDeg);
  if (failing < 0) throw std::runtime_error("OpenImageIO compare_Yee failed: " + bufB.geterror());
  error.perceptualFail = double(failing) / double(error.comparedPixels);
  return error;
}

}  // namespace bench
