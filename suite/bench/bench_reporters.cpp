#include "suite/bench/bench_reporters.h"

#include <cmath>
#include <optional>
#include <regex>
#include <sstream>
#include <string>
#include <unistd.h>

namespace bench {

std::string nullForNonFinite(const std::string& json) {
  // A value (after `":`), never text inside a string.
  static const std::regex nonFinite(R"((":\s*)-?(NaN|nan|Infinity|infinity|inf|Inf)\b)");
  return std::regex_replace(json, nonFinite, "$1null");
}

namespace {

// Google Benchmark appends the per-benchmark settings to every name
// ("/min_time:0.050/repeats:5/manual_time", "/real_time"); docs/bench-format.md's
// names have none, so the reporters drop them. (--benchmark_filter still sees
// them: end a pattern with `(/|$)`, not `$`.)
using Run = benchmark::BenchmarkReporter::Run;

// The mean aggregate of `counter` among `runs` (one benchmark's aggregates
// come in one ReportRuns call), if there is one.
std::optional<double> meanOf(const std::vector<Run>& runs, const Run& of, const std::string& counter) {
  for (const Run& r : runs)
    if (r.run_type == Run::RT_Aggregate && r.aggregate_name == "mean" && r.run_name.str() == of.run_name.str())
      if (const auto it = r.counters.find(counter); it != r.counters.end()) return it->second.value;
  return std::nullopt;
}

template <class Base>
class PlainNames : public Base {
 public:
  using Base::Base;
  void ReportRuns(const std::vector<Run>& runs) override {
    std::vector<Run> plain = runs;
    for (auto& run : plain) {
      // The cv aggregate of a counter that is 0 every time (err_perceptual_fail
      // of a clean image, `demoted` where nothing is demoted) is 0/0: nothing
      // varied, 0. Any other non-finite counter stays so (the JSON writes null):
      // the infinite err_max_abs of a broken image is no 0.
      if (run.run_type == Run::RT_Aggregate && run.aggregate_name == "cv")
        for (auto& [name, counter] : run.counters)
          if (std::isnan(counter.value) && meanOf(runs, run, name) == 0.0) counter.value = 0;
    }
    for (auto& run : plain) {
      run.run_name.min_time.clear();
      run.run_name.min_warmup_time.clear();
      run.run_name.iterations.clear();
      run.run_name.repetitions.clear();
      run.run_name.time_type.clear();
    }
    Base::ReportRuns(plain);
  }
};

// Google Benchmark's JSON writes a NaN or infinite number as NaN or Infinity,
// which is not JSON: null instead (docs/bench-format.md). Each call writes
// into a buffer, then the buffer, rewritten, to the real stream.
class PlainJson : public PlainNames<benchmark::JSONReporter> {
 public:
  bool ReportContext(const Context& context) override {
    bool ok = false;
    rewritten([&] { ok = PlainNames::ReportContext(context); });
    return ok;
  }
  void ReportRuns(const std::vector<Run>& runs) override {
    rewritten([&] { PlainNames::ReportRuns(runs); });
  }
  void Finalize() override {
    rewritten([&] { PlainNames::Finalize(); });
  }

 private:
  template <class Write>
  void rewritten(Write write) {
    std::ostream& out = GetOutputStream();
    std::ostringstream buffer;
    SetOutputStream(&buffer);
    write();
    SetOutputStream(&out);
    out << nullForNonFinite(buffer.str());
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
    reporters.display = std::make_unique<PlainJson>();
  if (outFile && outFormat == "json") reporters.file = std::make_unique<PlainJson>();
  return reporters;
}

}  // namespace bench
