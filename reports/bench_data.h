// Reading benchmark results (docs/bench-format.md): Google Benchmark's
// "benchmarks" arrays, alone or merged into bench.json, grouped into one
// entry per benchmark with its per-repetition times, its median (the
// "median" aggregate when Google Benchmark wrote one, else computed from the
// repetitions), spread and counters, plus the complexity fits (_BigO, _RMS).
// Nothing is trusted: a field that is missing or of another type reads as
// absent, never throws.
#pragma once

#include <nlohmann/json.hpp>

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace reports {

// `<kind>/<backend>/<scene>/<mode>[/<x>]`, after the parts Google Benchmark
// appends ("repeats:5", "min_time:...", "real_time", "manual_time", ...) are
// dropped. A name with fewer parts keeps what it has (kind = the whole name
// when there is no "/").
struct BenchName {
  std::string full;  // the name without Google Benchmark's attributes
  std::string kind, backend, scene, mode, x;
};
BenchName parseBenchName(std::string_view name);

// The x of a cost curve as a number: "64" -> 64, "1280x720" -> 921600 (pixels).
std::optional<double> curveX(std::string_view x);

struct BenchEntry {
  BenchName name;
  std::string section;           // the backend of bench.json it came from ("" for prepare / plain files)
  std::vector<double> repetitionsMs;  // real_time of each repetition, in ms, in file order
  std::optional<double> medianMs, meanMs, stddevMs, minMs, maxMs;
  std::vector<double> cpuRepetitionsMs;  // cpu_time of each repetition, in ms
  std::optional<double> cpuMedianMs;     // the median aggregate's cpu_time, else the repetitions' median
  // Coefficient of variation of real_time (0.05 = 5 %): Google Benchmark's
  // "cv" aggregate, else stddev / mean; nullopt with fewer than 2 repetitions.
  std::optional<double> cv;
  int count = 0;                 // repetitions (or 1 when only one run)
  bool medianFromAggregate = false;
  std::string error;             // error_message of a run that failed ("" otherwise)
  std::map<std::string, double> counters;  // median over repetitions, or the median aggregate's
  std::string label;
};

struct ComplexityFit {
  BenchName family;              // kind/backend/scene/mode, no x
  std::string bigO;              // "N", "NlgN", "N^2", "(1)", "lgN", "N^3", "f(N)"
  std::optional<double> coefficientMs;  // real_coefficient in ms
  std::optional<double> rms;            // normalised RMS (0.05 = 5 %)
  // coefficient * f(n) in ms; nullopt for "f(N)" or without a coefficient.
  std::optional<double> at(double n) const;
};

struct BenchSet {
  std::vector<BenchEntry> entries;      // in order of first appearance
  std::vector<ComplexityFit> fits;
};

// Milliseconds per unit of Google Benchmark's "time_unit" ("ns", "us", "ms", "s"; missing = "ns").
double msPerUnit(std::string_view timeUnit);

// Adds one Google Benchmark "benchmarks" array to `set`.
void addBenchmarks(BenchSet& set, const nlohmann::ordered_json& benchmarks, const std::string& section);

// Every benchmark of a bench.json (each backend's, then "prepare") or of a
// plain Google Benchmark file (its "benchmarks").
BenchSet readBenchFile(const nlohmann::ordered_json& file);

double median(std::vector<double> values);  // NaN when empty

}  // namespace reports
