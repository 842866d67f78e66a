// The timed loops: one draw benchmark (`frame`, `frame_readback`) and one
// pipeline benchmark, each filling Google Benchmark's state with the time and
// the counters of docs/bench-format.md. A failure skips the benchmark with
// its message; it never ends the process.
#pragma once

#include "suite/bench/bench_frame.h"
#include "suite/bench/run_state.h"

#include <benchmark/benchmark.h>

namespace bench {

// Draw (and read back) on the backend object shared by every draw benchmark
// of the run. Untimed first: the ideal reference (cached), the pipeline, and
// (but on a slow driver, where one frame takes seconds) one draw that uploads
// the geometry, allocates the targets and lets the driver finish its compile.
// The loop then times steady-state frames (uniform packing and upload
// included: draw() does it every call). The benchmark's time is the device's
// own time of the draw when the backend reports one that can be trusted
// (RunState::deviceTime; `frame` only: the readback is not in it), else
// wall-clock time; `wall_ms` is always there, `device_ms` when reported.
void timeFrame(benchmark::State& state, RunState& run, const BenchFrame& bench, bool withReadback);

// Pipelines are cached per backend object (in memory) and in the on-disk
// cache folder, so every iteration empties the folder and creates a fresh
// backend, neither of them timed (manual time): only preparePipeline() is
// measured, writing the pipeline cache back to the folder included. Drivers
// that compile state-dependent variants (lavapipe) finish part of their
// compile in the first draw, which this does not time.
void timePipeline(benchmark::State& state, RunState& run, const BenchFrame& bench);

}  // namespace bench
