// `lightcts bench` and `lightcts bench compare`, and the hidden
// `lightcts bench-worker` that `bench` starts once per backend combination.
#include "app/commands.h"
#include "app/exit_status.h"
#include "app/scene_input.h"
#include "imaging/atomic_file.h"
#include "imaging/image_codec_loader.h"
#include "reports/bench_compare.h"
#include "runner/bench_run.h"

#ifdef LIGHTCTS_WITH_BENCHMARKS
#include "suite/bench/frame_benchmarks.h"
#include "suite/bench/lighting_cost.h"
#include "suite/bench/prepare_benchmarks.h"
#endif

#include <nlohmann/json.hpp>

#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string_view>
#include <thread>
#include <vector>

namespace app {
namespace {

nlohmann::json readJson(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError("cannot read " + path);
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::parse_error& e) {
    throw InputError(path + ": not JSON: " + e.what());
  }
}

}  // namespace

int runBenchCommand(const runner::BenchOptions& options, std::ostream& out, std::ostream& err) {
  return guardCommand(err, [&] {
#ifndef LIGHTCTS_WITH_BENCHMARKS
    err << "lightcts: bench: this build has no benchmarks (LIGHTCTS_BUILD_BENCHMARKS=OFF) (NotSupported)\n";
    return kExitNotSupported;
#else
    try {
      imaging::requireImageModule();  // the error of each mode (compare_Yee) and the report's images
      return runner::runBench(options, out, err);
    } catch (const std::invalid_argument& e) {
      throw InputError(e.what());
    }
#endif
  });
}

int runBenchCompareCommand(const std::string& before, const std::string& after, std::ostream& out,
                           std::ostream& err) {
  return guardCommand(err, [&] { return reports::compareBench(readJson(before), readJson(after), out); });
}

int runBenchWorker(int argc, char** argv) {
  // argv: lightcts bench-worker KIND [Google Benchmark and our flags...]
#ifndef LIGHTCTS_WITH_BENCHMARKS
  (void)argc;
  (void)argv;
  std::cerr << "lightcts: bench-worker: this build has no benchmarks (NotSupported)\n";
  return kExitNotSupported;
#else
  if (argc < 3) {
    std::cerr << "lightcts: bench-worker: expected peak, prepare or frame\n";
    return kExitBadInput;
  }
  const std::string_view kind = argv[2];
  // What follows the kind, behind the program name, as Google Benchmark expects.
  std::vector<char*> rest = {argv[0]};
  for (int i = 3; i < argc; ++i) rest.push_back(argv[i]);
  rest.push_back(nullptr);
  const int restCount = int(rest.size()) - 1;
  if (kind == "frame") return bench::runFrameBenchmarks(restCount, rest.data());
  if (kind == "prepare") return bench::runPrepareBenchmarks(restCount, rest.data());
  if (kind == "peak") {
    std::string outFile;
    for (int i = 1; i < restCount; ++i)
      if (std::string_view a = rest[std::size_t(i)]; a.starts_with("--benchmark_out="))
        outFile = std::string(a.substr(16));
    constexpr int kRepetitions = 5;
    const double gflops = bench::measurePeakGflops(kRepetitions);
    const nlohmann::ordered_json peak = {
        {"peak",
         {{"gflops", gflops},
          {"cores", std::thread::hardware_concurrency()},
          {"kernel", "independent single-precision FMA chains on every core (suite/bench/peak_rate)"},
          {"median_of", kRepetitions}}}};
    std::cout << "peak " << gflops << " GFLOP/s\n";
    if (!outFile.empty()) imaging::writeFileAtomically(outFile, peak.dump(1) + "\n");
    return kExitSuccess;
  }
  std::cerr << "lightcts: bench-worker: unknown kind '" << kind << "'\n";
  return kExitBadInput;
#endif
}

}  // namespace app
