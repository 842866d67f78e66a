#include "comparison/vacuous_comparison.h"

#include <cstdio>

namespace comparison {

std::string vacuousComparisonReason(const PixelCounts& counts) {
  char text[256];
  if (counts.total > 0 && double(counts.compared) < kMinimumComparedShare * double(counts.total)) {
    std::snprintf(text, sizeof text,
                  "only %lld of %lld pixels are compared (%.2f%%, fewer than %.0f%%): the rest are masked",
                  counts.compared, counts.total, 100.0 * double(counts.compared) / double(counts.total),
                  100.0 * kMinimumComparedShare);
    return text;
  }
  if (counts.litCompared == 0) {
    std::snprintf(text, sizeof text,
                  "no compared pixel of the reference is above the flush-to-zero floor (2^-126): the frame is "
                  "black%s, so matching it checks nothing of the model",
                  counts.compared == 0 ? " and every pixel is masked" : "");
    return text;
  }
  return "";
}

}  // namespace comparison
