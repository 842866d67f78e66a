#include "reports/bench_data.h"

#include "reports/json_fields.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <set>
#include <unordered_map>

namespace reports {
namespace {

bool isAttribute(std::string_view part) {
  return part.find(':') != std::string_view::npos || part == "real_time" || part == "manual_time" ||
         part == "process_time";
}

// Keys Google Benchmark writes on every entry; any other number is a counter.
const std::set<std::string, std::less<>>& standardKeys() {
  static const std::set<std::string, std::less<>> keys = {
      "name", "family_index", "per_family_instance_index", "run_name", "run_type", "repetitions",
      "repetition_index", "threads", "iterations", "real_time", "cpu_time", "time_unit", "aggregate_name",
      "aggregate_unit", "error_occurred", "error_message", "label", "big_o", "cpu_coefficient",
      "real_coefficient", "rms", "complexity_n", "skipped"};
  return keys;
}

bool endsWith(std::string_view text, std::string_view suffix) {
  return text.size() >= suffix.size() && text.substr(text.size() - suffix.size()) == suffix;
}

// The aggregate name of an entry: "aggregate_name" when run_type is
// "aggregate"; for files without run_type, a known suffix of the name.
std::string aggregateOf(const Json& entry) {
  const std::string runType = textField(entry, "run_type");
  if (runType == "aggregate") return textField(entry, "aggregate_name");
  if (!runType.empty()) return "";
  const std::string name = textField(entry, "name");
  for (const char* suffix : {"mean", "median", "stddev", "cv", "BigO", "RMS"})
    if (endsWith(name, std::string("_") + suffix)) return suffix;
  return "";
}

// The run's name: "run_name", or "name" less "_<aggregate>".
std::string runNameOf(const Json& entry, const std::string& aggregate) {
  std::string runName = textField(entry, "run_name");
  if (!runName.empty()) return runName;
  std::string name = textField(entry, "name");
  if (!aggregate.empty() && endsWith(name, "_" + aggregate)) name.resize(name.size() - aggregate.size() - 1);
  return name;
}

struct Pending {
  BenchEntry entry;
  std::map<std::string, std::vector<double>> repetitionCounters;
  std::map<std::string, double> medianCounters;
  bool haveMedianCounters = false;
  std::optional<int> aggregateRepetitions;
};

void collectCounters(const Json& entry, std::map<std::string, std::vector<double>>& into) {
  for (auto it = entry.begin(); it != entry.end(); ++it)
    if (it->is_number() && !standardKeys().count(it.key())) into[it.key()].push_back(it->get<double>());
}

}  // namespace

BenchName parseBenchName(std::string_view name) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true) {
    const std::size_t slash = name.find('/', start);
    const std::string_view part = name.substr(start, slash == std::string_view::npos ? name.npos : slash - start);
    if (!isAttribute(part)) parts.emplace_back(part);
    if (slash == std::string_view::npos) break;
    start = slash + 1;
  }
  BenchName result;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    if (i) result.full += '/';
    result.full += parts[i];
  }
  std::string* fields[] = {&result.kind, &result.backend, &result.scene, &result.mode};
  for (std::size_t i = 0; i < parts.size() && i < 4; ++i) *fields[i] = parts[i];
  for (std::size_t i = 4; i < parts.size(); ++i) {  // x; anything past it stays part of x
    if (i > 4) result.x += '/';
    result.x += parts[i];
  }
  return result;
}

std::optional<double> curveX(std::string_view x) {
  if (x.empty()) return std::nullopt;
  const auto number = [](std::string_view text) -> std::optional<double> {
    if (text.empty()) return std::nullopt;
    std::string copy(text);
    char* end = nullptr;
    const double value = std::strtod(copy.c_str(), &end);
    if (end != copy.c_str() + copy.size() || !std::isfinite(value)) return std::nullopt;
    return value;
  };
  const std::size_t by = x.find('x');
  if (by == std::string_view::npos) return number(x);
  const auto w = number(x.substr(0, by)), h = number(x.substr(by + 1));
  if (!w || !h) return std::nullopt;
  return *w * *h;
}

std::optional<double> ComplexityFit::at(double n) const {
  if (!coefficientMs || n <= 0) return std::nullopt;
  const double lg = std::log2(n);
  double f = 0;
  if (bigO == "(1)") f = 1;
  else if (bigO == "N") f = n;
  else if (bigO == "lgN") f = lg;
  else if (bigO == "NlgN") f = n * lg;
  else if (bigO == "N^2") f = n * n;
  else if (bigO == "N^3") f = n * n * n;
  else return std::nullopt;
  return *coefficientMs * f;
}

double msPerUnit(std::string_view timeUnit) {
  if (timeUnit == "s") return 1e3;
  if (timeUnit == "ms") return 1;
  if (timeUnit == "us") return 1e-3;
  return 1e-6;  // "ns", Google Benchmark's default
}

double median(std::vector<double> values) {
  if (values.empty()) return std::nan("");
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

void addBenchmarks(BenchSet& set, const Json& benchmarks, const std::string& section) {
  if (!benchmarks.is_array()) return;
  std::vector<Pending> pending;
  std::unordered_map<std::string, std::size_t> index;
  const auto slot = [&](const BenchName& name) -> Pending& {
    const auto [it, added] = index.emplace(name.full, pending.size());
    if (added) {
      pending.emplace_back();
      pending.back().entry.name = name;
      pending.back().entry.section = section;
    }
    return pending[it->second];
  };

  for (const Json& entry : benchmarks) {
    if (!entry.is_object()) continue;
    const std::string aggregate = aggregateOf(entry);
    const BenchName name = parseBenchName(runNameOf(entry, aggregate));
    if (name.full.empty()) continue;
    const double unit = msPerUnit(textField(entry, "time_unit"));
    const std::optional<double> realTime = numberField(entry, "real_time");
    const std::optional<double> cpuTime = numberField(entry, "cpu_time");

    if (aggregate == "BigO" || aggregate == "RMS") {
      auto fit = std::find_if(set.fits.begin(), set.fits.end(),
                              [&](const ComplexityFit& f) { return f.family.full == name.full; });
      if (fit == set.fits.end()) {
        set.fits.emplace_back();
        fit = set.fits.end() - 1;
        fit->family = name;
      }
      if (aggregate == "BigO") {
        fit->bigO = textField(entry, "big_o");
        if (const auto c = numberField(entry, "real_coefficient")) fit->coefficientMs = *c * unit;
      } else if (const auto rms = numberField(entry, "rms")) {
        fit->rms = *rms;
      }
      continue;
    }

    Pending& p = slot(name);
    if (const auto label = textField(entry, "label"); !label.empty()) p.entry.label = label;
    const bool failed = entry.contains("error_occurred") && entry["error_occurred"] == true;
    if (failed) {
      p.entry.error = textField(entry, "error_message");
      if (p.entry.error.empty()) p.entry.error = "error";
      continue;
    }
    if (aggregate.empty()) {
      if (realTime) p.entry.repetitionsMs.push_back(*realTime * unit);
      if (cpuTime) p.entry.cpuRepetitionsMs.push_back(*cpuTime * unit);
      collectCounters(entry, p.repetitionCounters);
    } else if (aggregate == "median") {
      if (realTime) p.entry.medianMs = *realTime * unit, p.entry.medianFromAggregate = true;
      if (cpuTime) p.entry.cpuMedianMs = *cpuTime * unit;
      std::map<std::string, std::vector<double>> counters;
      collectCounters(entry, counters);
      for (const auto& [key, values] : counters) p.medianCounters[key] = values.front();
      p.haveMedianCounters = true;
      if (const auto reps = numberField(entry, "repetitions")) p.aggregateRepetitions = int(*reps);
    } else if (aggregate == "mean") {
      if (realTime) p.entry.meanMs = *realTime * unit;
    } else if (aggregate == "stddev") {
      if (realTime) p.entry.stddevMs = *realTime * unit;
    } else if (aggregate == "cv") {  // aggregate_unit "percentage": a fraction, no time unit
      if (realTime) p.entry.cv = *realTime;
    } else if (aggregate == "min") {  // ComputeStatistics("min", ...); the repetitions win when present
      if (realTime) p.entry.minMs = *realTime * unit;
    } else if (aggregate == "max") {
      if (realTime) p.entry.maxMs = *realTime * unit;
    }
  }

  for (Pending& p : pending) {
    BenchEntry& e = p.entry;
    const auto& reps = e.repetitionsMs;
    if (!reps.empty()) {
      if (!e.medianMs) e.medianMs = median(reps);
      e.minMs = *std::min_element(reps.begin(), reps.end());
      e.maxMs = *std::max_element(reps.begin(), reps.end());
      double sum = 0;
      for (double r : reps) sum += r;
      const double mean = sum / double(reps.size());
      if (!e.meanMs) e.meanMs = mean;
      if (!e.stddevMs && reps.size() >= 2) {
        double squares = 0;
        for (double r : reps) squares += (r - mean) * (r - mean);
        e.stddevMs = std::sqrt(squares / double(reps.size() - 1));  // sample stddev, as Google Benchmark
      }
    }
    e.count = !reps.empty() ? int(reps.size()) : p.aggregateRepetitions.value_or(e.medianMs ? 1 : 0);
    if (!e.cpuMedianMs && !e.cpuRepetitionsMs.empty()) e.cpuMedianMs = median(e.cpuRepetitionsMs);
    if (e.count < 2) e.cv.reset();
    else if (!e.cv && e.stddevMs && e.meanMs && *e.meanMs > 0) e.cv = *e.stddevMs / *e.meanMs;
    if (p.haveMedianCounters) {
      e.counters = p.medianCounters;
      for (const auto& [key, values] : p.repetitionCounters)  // counters only the repetitions have
        if (!e.counters.count(key)) e.counters[key] = median(values);
    } else {
      for (const auto& [key, values] : p.repetitionCounters) e.counters[key] = median(values);
    }
    set.entries.push_back(std::move(e));
  }
}

BenchSet readBenchFile(const Json& file) {
  BenchSet set;
  if (!file.is_object()) return set;
  // A plain Google Benchmark file; bench.json's flat top-level copy (for
  // Google Benchmark's tools) repeats what "backends" and "prepare" hold.
  if (file.contains("benchmarks") && !file.contains("backends"))
    addBenchmarks(set, arrayField(file, "benchmarks"), "");
  for (const Json& backend : arrayField(file, "backends"))
    addBenchmarks(set, arrayField(backend, "benchmarks"), textField(backend, "backend"));
  addBenchmarks(set, arrayField(objectField(file, "prepare"), "benchmarks"), "");
  return set;
}

}  // namespace reports
