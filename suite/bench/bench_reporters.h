// The reporters both benchmark programs (the frame benchmarks and the CPU
// preparation benchmarks) run with: Google Benchmark's console and JSON
// reporters, but with the plain names of docs/bench-format.md and null, not
// NaN or Infinity, in the JSON.
#pragma once

#include <benchmark/benchmark.h>

#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace bench {

struct Reporters {
  std::unique_ptr<benchmark::BenchmarkReporter> display;  // null: Google Benchmark's own (csv)
  std::unique_ptr<benchmark::BenchmarkReporter> file;     // null: no --benchmark_out, or not JSON
};

// The console's, unless --benchmark_format asks for another; the file's when
// --benchmark_out writes JSON (the default format). CSV keeps Google
// Benchmark's own, names unchanged. `flags`: the Google Benchmark flags given.
Reporters plainNameReporters(const std::vector<std::string_view>& flags);

// `json` with every NaN or infinite value (NaN, Infinity, -Infinity, nan,
// inf) written as null; text inside strings is left alone.
std::string nullForNonFinite(const std::string& json);

}  // namespace bench
