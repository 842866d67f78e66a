// `lightcts bench`: the frame benchmarks of every backend
// combination asked for, each in a process of its own (Mesa loads one driver
// per process; a driver crash costs one combination, not the run), the CPU
// preparation benchmarks, and the peak-rate calibration, merged into
// DIR/bench.json (docs/bench-format.md) and written as HTML pages
// (DIR/index.html, DIR/<backend>.html). bench.json also carries Google
// Benchmark's top-level "context" and "benchmarks" (every backend's entries
// in one array), so that Google Benchmark's tools/compare.py reads it.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

namespace runner {

struct BenchOptions {
  std::vector<std::string> backends;  // combination suffixes or API names; empty: all
  std::string outDir;
  std::string scenesDir = "suite/scenes";
  bool quick = false;                 // fewer points and repetitions (smoke tests)
  bool fullSet = false;               // every combination the full set, however slow its driver
  double timeoutSeconds = 900;        // per benchmark process
  // The errors kept across runs (frame processes' --error_cache); "" for
  // none (`--fresh-errors`): this run's errors only, in raw/ideal.
  std::string errorCache;
  std::string workerExecutable;       // the lightcts binary (/proc/self/exe)
  std::string commandLine;
};

// Exit status: 0 when every combination asked for ran or is NotSupported
// and at least one ran; 3 when none is present; 4 when a benchmark process
// failed. Throws std::invalid_argument for an unknown backend.
int runBench(const BenchOptions& options, std::ostream& out, std::ostream& err);

}  // namespace runner
