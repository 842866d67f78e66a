// The wall clock every benchmark file reads for manual times and untimed
// measurements (bakes, the time-source calibration).
#pragma once

#include <chrono>

namespace bench {

using Clock = std::chrono::steady_clock;

inline double millisecondsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

}  // namespace bench
