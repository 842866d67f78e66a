#include "conformance/brightness_sharpness.h"

#include "comparison/image_comparison.h"

#include <cmath>
#include <limits>

namespace conformance {
namespace {

struct ScaleMutant {
  const imaging::Image& result;
  const imaging::Image& lightPart;
  const reference::ReferenceImages& reference;
  const lighting::Expectation& expect;

  // Whether the result with the lights `change` brighter (relative) fails.
  bool fails(double change) const {
    imaging::Image scaled = result;
    for (int j = 0; j < scaled.height; ++j)
      for (int i = 0; i < scaled.width; ++i)
        for (int c = 0; c < 3; ++c)
          scaled.at(i, j, c) = float(double(scaled.at(i, j, c)) + change * double(lightPart.at(i, j, c)));
    return comparison::compareImages(scaled, reference, expect, 0).verdict == comparison::Verdict::Fail;
  }

  // The smallest e in (0, 1] with fails(sign e), bisected.
  double smallestFailing(double sign) const {
    if (!fails(sign)) return std::numeric_limits<double>::infinity();
    double passes = 0, failing = 1;
    while (failing - passes > kSharpnessPrecision * failing) {
      const double middle = 0.5 * (passes + failing);
      (fails(sign * middle) ? failing : passes) = middle;
    }
    return failing;
  }
};

}  // namespace

CaughtScale smallestCaughtScale(const imaging::Image& result, const imaging::Image& lightPart,
                                const reference::ReferenceImages& reference, const lighting::Expectation& expect) {
  const ScaleMutant mutant{result, lightPart, reference, expect};
  if (mutant.fails(0.0)) return {0.0, 0.0};
  return {mutant.smallestFailing(1.0), mutant.smallestFailing(-1.0)};
}

}  // namespace conformance
