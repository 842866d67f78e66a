// Speed of the rendering backends (SPEC 9), one backend combination per run:
//   render_bench --backend=vulkan|gl-egl|gl-osmesa [--driver=softpipe] [--quick]
//                [--peak_gflops=X] [Google Benchmark flags]
// frame_benchmarks.h has the flags, docs/bench-format.md the names and counters.
#include "suite/bench/frame_benchmarks.h"

int main(int argc, char** argv) { return bench::runFrameBenchmarks(argc, argv); }
