#include "suite/bench/bench_registrar.h"

#include "results/bench_names.h"
#include "suite/bench/frame_timer.h"

#include <algorithm>
#include <exception>
#include <optional>
#include <vector>

namespace bench {
namespace {

double minimum(const std::vector<double>& v) { return v.empty() ? 0.0 : *std::min_element(v.begin(), v.end()); }
double maximum(const std::vector<double>& v) { return v.empty() ? 0.0 : *std::max_element(v.begin(), v.end()); }

// Repetitions with aggregates (mean, median, stddev, cv, min, max) in the
// JSON beside every repetition (the compare tool's U-test needs those); the
// console shows the aggregates only.
void configure(benchmark::internal::Benchmark* b, const Timing& timing) {
  b->Unit(benchmark::kMillisecond)->UseManualTime()->Repetitions(timing.repetitions)->DisplayAggregatesOnly(true);
  b->ComputeStatistics("min", minimum)->ComputeStatistics("max", maximum);
  if (timing.iterations > 0) b->Iterations(timing.iterations);
  else b->MinTime(timing.minTime);
}

// `made` = make() on a benchmark's first run (scenes are built only for the
// benchmarks a filter keeps); a failure skips the benchmark with its message.
template <class Made, class Make>
bool makeOnce(benchmark::State& st, Made& made, const Make& make) {
  try {
    if (!made) made = make();
  } catch (const std::exception& e) {
    st.SkipWithError(e.what());
    return false;
  }
  return true;
}

// The lazy frame, made on the benchmark's first run; null (the benchmark
// skipped with the message) when making it fails.
const BenchFrame* madeFrame(benchmark::State& st, LazyBenchFrame& bench) {
  try {
    return &bench.get();
  } catch (const std::exception& e) {
    st.SkipWithError(e.what());
    return nullptr;
  }
}

}  // namespace

// --quick proves each benchmark runs and measures nothing: one
// iteration, one repetition, on every driver. A slow driver (by its
// measured speed, driver_speed.h: seconds a frame): one iteration, 3
// repetitions. Otherwise 5: with 3
// against 3, `lightcts bench compare`'s Mann-Whitney U is never significant
// (its smallest p is 0.1), so no slowdown could ever be shown.
Registrar::Registrar(std::shared_ptr<RunState> run) : run_(std::move(run)) {
  if (run_->settings.quick) {
    frameTiming_ = pipelineTiming_ = {1, 0, 1};
  } else if (run_->slow()) {
    frameTiming_ = {3, 0, 1};
    pipelineTiming_ = {3, 0.05, 0};
  } else {
    frameTiming_ = {5, 0.05, 0};
    pipelineTiming_ = frameTiming_;
  }
}

std::string Registrar::name(std::string_view kind, const std::string& scene, const std::string& mode,
                            const std::string& x) const {
  std::string text(kind);
  text.append("/").append(run_->suffix()).append("/").append(scene).append("/").append(mode);
  if (!x.empty()) text.append("/").append(x);
  return text;
}

void Registrar::frame(const std::string& scene, const std::string& mode, const std::string& x, const LazyFrame& bench,
                      bool withReadback) {
  auto run = run_;
  const std::string benchmarkName = name(withReadback ? results::bench::kFrameReadback : results::bench::kFrame, scene, mode, x);
  if (bench->hasError()) errorCandidates_.push_back({benchmarkName, bench});
  configure(benchmark::RegisterBenchmark(benchmarkName.c_str(),
                                         [run, bench, withReadback](benchmark::State& st) {
                                           if (const BenchFrame* made = madeFrame(st, *bench))
                                             timeFrame(st, *run, *made, withReadback);
                                         }),
            frameTiming_);
}

void Registrar::upload(const std::string& scene, const std::string& mode, const std::string& x, MakeFrame make) {
  auto run = run_;
  auto made = std::make_shared<std::optional<lighting::Frame>>();
  configure(benchmark::RegisterBenchmark(name(results::bench::kUpload, scene, mode, x).c_str(),
                                         [run, made, make = std::move(make)](benchmark::State& st) {
                                           if (makeOnce(st, *made, make)) timeUpload(st, *run, **made);
                                         }),
            pipelineTiming_);
}

void Registrar::pipeline(const std::string& scene, const std::string& mode, const LazyFrame& bench) {
  auto run = run_;
  configure(benchmark::RegisterBenchmark(name(results::bench::kPipeline, scene, mode, "").c_str(),
                                         [run, bench](benchmark::State& st) {
                                           if (const BenchFrame* made = madeFrame(st, *bench))
                                             timePipeline(st, *run, *made);
                                         }),
            pipelineTiming_);
}

}  // namespace bench
