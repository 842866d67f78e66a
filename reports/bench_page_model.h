// What the benchmark pages (bench_report.h) are written from: bench.json read
// once (BenchModel), and the questions every section asks of an entry (a
// counter, its backend, its kind, its lightmap resolution), with the number
// format of every table. Internal to reports/.
#pragma once

#include "reports/bench_data.h"
#include "reports/json_fields.h"
#include "reports/two_term_limit.h"

#include <cstddef>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace reports::benchpages {

using Entries = std::vector<const BenchEntry*>;
using Keep = std::function<bool(const BenchEntry&)>;

struct BenchModel {
  const Json& bench;
  BenchSet set;
  std::vector<std::string> backends;  // page order and colours
  std::vector<std::string> modes;     // colour order on backend pages
  // Each backend's two-term limit (two_term_limit.h), fitted to its
  // all-lights light curve; absent for a backend without that curve.
  std::map<std::string, TwoTermFit> twoTerm;

  explicit BenchModel(const Json& b);
  std::size_t backendIndex(const std::string& name) const;
  std::size_t modeIndex(const std::string& name) const;
  Entries select(const Keep& keep) const;  // of every entry, in file order
};

// The entries of `entries` that `keep` keeps, in order.
Entries filter(const Entries& entries, const Keep& keep);
Entries ofScene(const Entries& entries, const std::string& scene);

// A table's number: integers in full (921600, not 9.216e+05), else `digits`
// significant digits; "-" for none or non-finite.
std::string fmt(double v, int digits = 4);
std::string fmt(const std::optional<double>& v, int digits = 4);

std::optional<double> counter(const BenchEntry& e, std::string_view key);  // key: results/bench_names.h
// The median over limit_ms (docs/performance.md, the physical limit).
std::optional<double> limitRatio(const BenchEntry& e);
// The median over the entry's two-term estimate (its backend's fit at its
// pixels and lights_per_pixel); nullopt without a fit or a load.
std::optional<double> twoTermRatio(const BenchModel& m, const BenchEntry& e);
// The bench.json section it came from, else the backend its name says.
std::string backendOf(const BenchEntry& e);
// The backends of `entries` (backendOf), each once, in the order they first appear.
std::vector<std::string> backendsOf(const Entries& entries);

bool isPrepare(const BenchEntry& e);
// A benchmark whose image had NaN or infinite pixels (err_nonfinite_pixels
// > 0): it has no error (err_rmse is null), and no page shows it as a point.
bool isBroken(const BenchEntry& e);
// A `frame` benchmark with a time and a finite err_rmse, not broken: a point
// of the speed-against-error plot.
bool hasError(const BenchEntry& e);
// N of a `lightmap-N` mode (docs/bench-format.md); nullopt for other modes.
std::optional<double> lightmapResolution(const BenchEntry& e);
// A point of a cost curve: scene curve-*, a numeric x and a time.
bool isCurve(const BenchEntry& e);

// Scenes in first-appearance order, the synthetic lights64-1280x720 first,
// then the lightmap scenes and the curves.
std::vector<std::string> scenesOf(const Entries& entries);
// The x axis of a curve scene ("lights" for curve-lights).
std::string xAxisLabel(const std::string& scene);

}  // namespace reports::benchpages
