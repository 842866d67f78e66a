// Registers the frame benchmarks with Google Benchmark under the names of
// docs/bench-format.md (`<kind>/<combination>/<scene>/<mode>[/<x>]`), with
// the run's repetitions and statistics: what every benchmark family calls,
// so that names and timing are decided here only.
#pragma once

#include "suite/bench/bench_frame.h"
#include "suite/bench/error_prepass.h"
#include "suite/bench/run_state.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace bench {

// How a benchmark repeats: a fixed iteration count, or Google Benchmark's
// own choice for at least minTime seconds (of the benchmark's time) per repetition.
struct Timing {
  int repetitions = 5;
  double minTime = 0.05;
  int iterations = 0;  // 0: chosen by Google Benchmark
};

class Registrar {
 public:
  explicit Registrar(std::shared_ptr<RunState> run);

  // frame/... or, withReadback, frame_readback/...; `x` empty: no /<x>. The
  // frame is made on the benchmark's first run (or by the error prepass),
  // only when the filter selects it.
  void frame(const std::string& scene, const std::string& mode, const std::string& x, const LazyFrame& bench,
             bool withReadback);

  void pipeline(const std::string& scene, const std::string& mode, const LazyFrame& bench);

  // upload/...: the textures of `make`'s frame (made on the first run, as
  // a LazyFrame is) uploaded by the shipped-shader backend (timeUpload).
  using MakeFrame = std::function<lighting::Frame()>;
  void upload(const std::string& scene, const std::string& mode, const std::string& x, MakeFrame make);

  const RunState& run() const { return *run_; }
  // The frame benchmarks with error counters, in registration order: what
  // precomputeErrors may compute before the timed runs.
  const std::vector<ErrorCandidate>& errorCandidates() const { return errorCandidates_; }

 private:
  std::string name(std::string_view kind, const std::string& scene, const std::string& mode, const std::string& x) const;

  std::shared_ptr<RunState> run_;
  Timing frameTiming_, pipelineTiming_;
  std::vector<ErrorCandidate> errorCandidates_;  // upload: pipelineTiming_ (Google Benchmark's count, also on softpipe)
};

}  // namespace bench
