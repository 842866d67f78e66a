// CPU frame preparation benchmarks (docs/bench-format.md kind
// `prepare`, docs/performance.md): light selection (SPEC 5.1, 5.2) and the
// packing every backend does, per frame; the shadow-mask channel assignment
// (SPEC 5.3, bake time) apart.
#pragma once

namespace bench {

// Google Benchmark's main over the `prepare/cpu/...` benchmarks: registers
// them (once per process), then parses argv as Google Benchmark does. Our own
// flag `--quick` (removed before Google Benchmark sees argv) runs fewer points,
// one repetition and a short minimum time: a smoke test, not a measurement.
// Returns the process exit status (0, or 2 for an unknown argument).
int runPrepareBenchmarks(int argc, char** argv);

}  // namespace bench
