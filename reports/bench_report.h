// The performance pages of `lightcts bench` (docs/bench-report.md):
// bench.json (docs/bench-format.md) -> DIR/index.html (every backend) and
// DIR/<backend>.html (one per backend). Self-contained: inline SVG plots and
// CSS, no script, no external resource.
#pragma once

#include <nlohmann/json.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace reports {

// Writes outDir/index.html and outDir/<benchPageFile(backend)> for every
// backend of bench.json (and any other that only benchmark names mention),
// each atomically. Throws std::runtime_error when a file cannot be written,
// std::invalid_argument when `bench` is not an object or its "format" is
// not "lightcts-bench".
void writeBenchReport(const nlohmann::ordered_json& bench, const std::filesystem::path& outDir);

// The pages as text (what writeBenchReport writes).
std::string benchOverviewHtml(const nlohmann::ordered_json& bench);
std::string benchBackendHtml(const nlohmann::ordered_json& bench, const std::string& backend);

// Every backend a page is written for, in bench.json order.
std::vector<std::string> benchBackends(const nlohmann::ordered_json& bench);

// The page of a backend: its name with every byte outside [A-Za-z0-9._-]
// as "_", plus ".html" ("backend-index.html" for a backend named "index").
std::string benchPageFile(const std::string& backend);

// For (time, error) points: true for those on the Pareto front, i.e. no
// other point is at least as fast and at least as accurate and strictly
// better in one of the two. Equal points are all on the front.
std::vector<bool> paretoFront(const std::vector<std::pair<double, double>>& points);

// The peak-rate calibration run before and after the timed runs:
// the machine's load can swing it 4x, so a run whose two calibrations differ
// was timed on a machine that changed under it. `difference` is
// |after - before| / min(before, after), symmetric in the two and never
// below the plain relative change; `flagged` when it exceeds kPeakDriftLimit
// (0.2: 100 against 125 is 0.25, flagged; 100 against 115 is 0.15, not).
inline constexpr double kPeakDriftLimit = 0.2;
struct PeakDrift {
  double difference = 0;
  bool flagged = false;
};
// nullopt when either rate is missing or not positive (no comparison).
std::optional<PeakDrift> peakDrift(std::optional<double> beforeGflops, std::optional<double> afterGflops);
// The same from bench.json's "peak" and "peak_after" objects ("gflops").
std::optional<PeakDrift> peakDriftOf(const nlohmann::ordered_json& bench);

}  // namespace reports
