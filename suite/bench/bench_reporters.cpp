#include "suite/bench/bench_reporters.h"

#include <cmath>
#include <string>
#include <unistd.h>

namespace bench {
namespace {

// Google Benchmark appends the per-benchmark settings to every name
// ("/min_time:0.050/repeats:5/manual_time", "/real_time"); docs/bench-format.md's
// names have none, so the reporters drop them. (--benchmark_filter still sees
// them: end a pattern with `(/|$)`, not `$`.)
template <class Base>
class PlainNames : public Base {
 public:
  using Base::Base;
  void ReportRuns(const std::vector<benchmark::BenchmarkReporter::Run>& runs) override {
    std::vector<benchmark::BenchmarkReporter::Run> plain = runs;
    for (auto& run : plain) {
      run.run_name.min_time.clear();
      run.run_name.min_warmup_time.clear();
      run.run_name.iterations.clear();
      run.run_name.repetitions.clear();
      run.run_name.time_type.clear();
      // The cv aggregate of a counter that is 0 every time (err_perceptual_fail
      // of a clean image, `demoted` where nothing is demoted) is 0/0; JSON has
      // no NaN, and nothing varied: 0.
      for (auto& [name, counter] : run.counters)
        if (!std::isfinite(counter.value)) counter.value = 0;
    }
    Base::ReportRuns(plain);
  }
};

}  // namespace

Reporters plainNameReporters(const std::vector<std::string_view>& flags) {
  constexpr std::string_view kFormat = "--benchmark_format=", kOutFormat = "--benchmark_out_format=",
                             kOut = "--benchmark_out=";
  std::string displayFormat = "console", outFormat = "json";
  bool outFile = false;
  for (const std::string_view a : flags) {
    if (a.starts_with(kFormat)) displayFormat = std::string(a.substr(kFormat.size()));
    else if (a.starts_with(kOutFormat)) outFormat = std::string(a.substr(kOutFormat.size()));
    else if (a.starts_with(kOut)) outFile = a.size() > kOut.size();
  }
  Reporters reporters;
  if (displayFormat == "console")
    reporters.display = std::make_unique<PlainNames<benchmark::ConsoleReporter>>(
        ::isatty(STDOUT_FILENO) ? benchmark::ConsoleReporter::OO_ColorTabular : benchmark::ConsoleReporter::OO_Tabular);
  else if (displayFormat == "json")
    reporters.display = std::make_unique<PlainNames<benchmark::JSONReporter>>();
  if (outFile && outFormat == "json") reporters.file = std::make_unique<PlainNames<benchmark::JSONReporter>>();
  return reporters;
}

}  // namespace bench
