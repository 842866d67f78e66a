// The frames' errors against their ideal references, computed before the
// timed runs and on every core (the full bench's budget).
//
// OpenImageIO's compare_Yee (image_error.h) runs on one thread and takes
// about 3 s at 1280x720: run between the timed draws it would be some 40% of
// a frame process's time, all of it untimed. So before Google Benchmark starts, every frame
// with an error counter that the filter selects is drawn once and read back
// on the main thread, and its error is computed on a pool of one thread per
// core while the next frame draws. Nothing is timed meanwhile; a GL backend
// makes its context current on every call, so drawing here in any order
// leaves the timed benchmarks nothing to undo. The frames the filter selects
// are made first (LazyBenchFrame; the lightmap modes bake and time their
// bakes), before any thread of the pool runs. The timed benchmarks then find
// the error in RunState::errors; a failure here is left for the benchmark to
// report.
#pragma once

#include "suite/bench/bench_frame.h"
#include "suite/bench/run_state.h"

#include <memory>
#include <string>
#include <vector>

namespace bench {

// A benchmark whose error the prepass may compute: its name as registered
// (what --benchmark_filter sees, less Google Benchmark's suffixes) and frame.
struct ErrorCandidate {
  std::string name;
  LazyFrame bench;  // made here when the filter selects `name` (its benchmark then uses it)
};

// Whether Google Benchmark's --benchmark_filter `filter` (a regular
// expression searched for in the name; "" or "all" every one; a leading '-'
// negates) may select `name`. Given the name with and without a trailing "/",
// so that the `(/|$)` patterns of the smoke tests match either way.
bool filterSelects(const std::string& filter, const std::string& name);

// Fills run.errors for the candidates the filter selects (each error key once).
void precomputeErrors(RunState& run, const std::vector<ErrorCandidate>& candidates, const std::string& filter);

}  // namespace bench
