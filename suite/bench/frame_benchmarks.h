// The frame benchmarks of one backend combination (docs/bench-format.md):
// `frame`, `frame_readback` and `pipeline` on the synthetic 1280x720
// 64-light field in every mode, the cost curves, and (with --suite_scenes)
// every suite scene. `render_bench` is a thin main around it;
// `lightcts bench-worker frame` calls it too.
#pragma once

namespace bench {

// Our flags, taken out before Google Benchmark sees the rest (bench_settings.h):
//   --backend=vulkan|gl-egl|gl-osmesa   (default vulkan; backends::specBackendNames)
//   --driver=llvmpipe|softpipe|...      (a driver of that backend in backends/backend_combinations.def)
//   --set=auto|full|scaled              the full or the scaled-down set; auto (default): by the
//                                        driver's measured speed (driver_speed.h)
//   --peak_gflops=X                     adds the limit_ms and flops_per_pixel_light counters
//   --quick                             fewer points and repetitions (the ctest smoke test)
//   --scenes=DIR                        suite scenes (default: the source tree's suite/scenes)
//   --suite_scenes                      also time every suite scene (frame kind)
//   --cluster_tile=N, --cluster_slices=N the clustered mode's grid (default 16 pixels, 16 slices)
//   --field_size=WxH                    tests only: the 64-light field at W x H, whatever the set
//                                        (a smoke test of a full-set mode on a small frame)
//   --mutant=NAME                       tests only: draw that mutant (shaders/shader_variant.h),
//                                        a broken image to time (bench.broken-smoke)
// Every other argument goes to Google Benchmark (--benchmark_out=FILE,
// --benchmark_out_format=json, --benchmark_filter=...). One combination
// per process: Mesa loads one driver per process.
// Returns 0, 2 (bad usage), 3 (the backend or driver is not here: the first
// line on stderr says why; no benchmark ran) or 4 (it failed to start).
int runFrameBenchmarks(int argc, char** argv);

}  // namespace bench
