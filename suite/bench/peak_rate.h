// The calibrated peak-rate kernel (docs/performance.md): the
// machine's single-precision floating-point rate over every core, the
// denominator of the physical limit.
#pragma once

#include <string>

namespace bench {

struct PeakRate {
  double gflops = 0;    // median over the repetitions, all cores together
  int threads = 0;      // one per hardware thread (std::thread::hardware_concurrency)
  int repetitions = 0;
  std::string kernel;   // what ran: "avx2+fma ..." or "sse2 ..." (see peak_rate.cpp)
  double checksum = 0;  // the sum of the accumulators: finite and positive when the kernel ran sanely
};

// Calibrates the iteration count so that one run on one core lasts about
// `secondsPerRun`, then times `repetitions` runs on every hardware thread at
// once (std::thread, steady_clock) and takes the median.
PeakRate measurePeakRate(int repetitions = 5, double secondsPerRun = 0.2);

}  // namespace bench
