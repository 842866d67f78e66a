// `prepare_bench`: the CPU preparation benchmarks on their own
// (suite/bench/prepare_benchmarks.h; `lightcts bench` runs the same).
#include "suite/bench/prepare_benchmarks.h"

int main(int argc, char** argv) { return bench::runPrepareBenchmarks(argc, argv); }
