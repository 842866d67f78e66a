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

// Texture uploads (SPEC 3.10's cookies, and any baked maps): every iteration
// copies `frame`'s prepared scene into a fresh one (untimed: manual time), so
// that the shipped-shader backend, which uploads once per prepared scene,
// must upload again; only prepareTextures() is timed (releasing the previous
// scene's textures included). One untimed upload first (first-use
// allocations). Vulkan waits for the copy to finish inside prepareTextures;
// GL times the calls (llvmpipe copies the texels in them). Afterwards the
// next draw benchmark warms up again (RunState::lastDrawn), so it never
// times the upload of its own textures.
void timeUpload(benchmark::State& state, RunState& run, const lighting::Frame& frame);

}  // namespace bench
