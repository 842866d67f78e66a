// Comparing two benchmark runs (bench.json files or plain Google Benchmark
// JSON files, in any mix): for every benchmark both have, the medians, the
// change and a two-sided Mann-Whitney U test over the per-repetition times,
// so that a review sees which changes are beyond the noise.
#pragma once

#include <nlohmann/json.hpp>

#include <ostream>

namespace reports {

struct CompareOptions {
  double alpha = 0.05;             // "significant" when p < alpha
  double regressionPercent = 5.0;  // a regression: significant and slower by more than this
};

// Prints one line per benchmark present in both (median before and after in
// ms, change %, n, U, p, exact or normal, and "significant", "SLOWER" or
// "faster"), then a summary. Returns 1 when some benchmark is significantly
// slower by more than options.regressionPercent, else 0.
int compareBench(const nlohmann::json& before, const nlohmann::json& after, std::ostream& out);
int compareBench(const nlohmann::json& before, const nlohmann::json& after, std::ostream& out,
                 const CompareOptions& options);

}  // namespace reports
