#include "conformance/popping.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace conformance {

imaging::Image idealError(const imaging::Image& result, const reference::ReferenceImages& ideal, double& maxError) {
  if (result.width != ideal.value.width || result.height != ideal.value.height)
    throw std::invalid_argument("idealError: the result and the ideal reference differ in size");
  imaging::Image error(result.width, result.height, 3);
  maxError = 0;
  for (int y = 0; y < result.height; ++y)
    for (int x = 0; x < result.width; ++x) {
      const bool compared = ideal.value.at(x, y, 3) != 0.0f;
      for (int c = 0; c < 3; ++c) {
        const double e = compared ? double(result.at(x, y, c)) - ideal.value.at(x, y, c)
                                  : std::numeric_limits<double>::quiet_NaN();
        error.at(x, y, c) = float(e);
        if (std::isfinite(e)) maxError = std::max(maxError, std::abs(e));
      }
    }
  return error;
}

double poppingJump(const imaging::Image& previous, const imaging::Image& current) {
  if (previous.pixels.size() != current.pixels.size())
    throw std::invalid_argument("poppingJump: the frames differ in size");
  double jump = 0;
  for (std::size_t i = 0; i < current.pixels.size(); ++i) {
    const double d = std::abs(double(current.pixels[i]) - previous.pixels[i]);
    if (std::isfinite(d)) jump = std::max(jump, d);
  }
  return jump;
}

}  // namespace conformance
