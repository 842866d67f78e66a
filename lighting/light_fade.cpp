#include "lighting/light_fade.h"

namespace lighting {

double fadeWeight(double d2, double start, double cut) {
  if (d2 >= cut) return 0.0;
  if (d2 <= start) return 1.0;
  return (cut - d2) / (cut - start);  // start < d2 < cut: the divisor is > 0
}

std::vector<double> fadeWeights(const std::vector<double>& keptDistanceSquared,
                                std::optional<double> firstDroppedDistanceSquared, int fadeCount) {
  const int kept = int(keptDistanceSquared.size());
  std::vector<double> weights(kept, 1.0);
  if (fadeCount <= 0 || !firstDroppedDistanceSquared || kept == 0) return weights;
  const double cut = *firstDroppedDistanceSquared;
  const int startRank = kept - fadeCount - 1;  // 0-based; the last N kept lights follow it
  const double start = startRank >= 0 ? keptDistanceSquared[startRank] : 0.0;
  for (int k = 0; k < kept; ++k) weights[k] = fadeWeight(keptDistanceSquared[k], start, cut);
  return weights;
}

}  // namespace lighting
