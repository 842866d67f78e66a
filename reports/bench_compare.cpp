#include "reports/bench_compare.h"

#include "reports/bench_data.h"
#include "reports/bench_stats.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>

namespace reports {
namespace {

std::string fmt(const char* format, double v) {
  char text[64];
  std::snprintf(text, sizeof text, format, v);
  return text;
}

std::string pad(std::string text, std::size_t width, bool right = false) {
  if (text.size() >= width) return text;
  const std::string fill(width - text.size(), ' ');
  return right ? fill + text : text + fill;
}

}  // namespace

int compareBench(const nlohmann::json& before, const nlohmann::json& after, std::ostream& out) {
  return compareBench(before, after, out, CompareOptions{});
}

int compareBench(const nlohmann::json& before, const nlohmann::json& after, std::ostream& out,
                 const CompareOptions& options) {
  const BenchSet a = readBenchFile(nlohmann::ordered_json::parse(before.dump()));
  const BenchSet b = readBenchFile(nlohmann::ordered_json::parse(after.dump()));
  std::map<std::string, const BenchEntry*> byName;
  for (const BenchEntry& e : a.entries) byName.emplace(e.name.full, &e);

  std::size_t nameWidth = 9;
  for (const BenchEntry& e : b.entries)
    if (byName.count(e.name.full)) nameWidth = std::max(nameWidth, e.name.full.size());

  out << pad("benchmark", nameWidth) << "  " << pad("before ms", 11, true) << "  " << pad("after ms", 11, true)
      << "  " << pad("change", 9, true) << "  " << pad("n", 5, true) << "  " << pad("U", 6, true) << "  "
      << pad("p", 8, true) << "        verdict\n";
  int compared = 0, slower = 0, faster = 0, significant = 0, onlyAfter = 0;
  std::map<std::string, bool> matched;
  for (const BenchEntry& e : b.entries) {
    const auto it = byName.find(e.name.full);
    if (it == byName.end()) {
      ++onlyAfter;
      continue;
    }
    matched[e.name.full] = true;
    const BenchEntry& old = *it->second;
    out << pad(e.name.full, nameWidth) << "  ";
    if (!old.medianMs || !e.medianMs) {
      out << "no time " << (!old.medianMs ? "before" : "after")
          << (old.error.empty() && e.error.empty() ? "" : " (error: " + (old.error.empty() ? e.error : old.error) + ")")
          << '\n';
      continue;
    }
    ++compared;
    const double change = *old.medianMs > 0 ? (*e.medianMs - *old.medianMs) / *old.medianMs * 100 : NAN;
    out << pad(fmt("%.4g", *old.medianMs), 11, true) << "  " << pad(fmt("%.4g", *e.medianMs), 11, true) << "  "
        << pad(fmt("%+.1f%%", change), 9, true) << "  "
        << pad(std::to_string(old.repetitionsMs.size()) + "/" + std::to_string(e.repetitionsMs.size()), 5, true)
        << "  ";
    if (old.repetitionsMs.empty() || e.repetitionsMs.empty()) {
      out << pad("-", 6, true) << "  " << pad("-", 8, true) << "        no repetitions to test\n";
      continue;
    }
    const MannWhitney test = mannWhitneyU(old.repetitionsMs, e.repetitionsMs);
    std::string verdict;
    if (test.p < options.alpha) {
      ++significant;
      verdict = "significant";
      if (change > options.regressionPercent) verdict = "SLOWER (significant, > " + fmt("%g", options.regressionPercent) + "%)", ++slower;
      else if (change < -options.regressionPercent) verdict = "faster (significant)", ++faster;
    }
    out << pad(fmt("%g", test.u), 6, true) << "  " << pad(fmt("%.4f", test.p), 8, true) << "  "
        << (test.exact ? "exact " : "normal") << "  " << verdict << '\n';
  }
  int onlyBefore = 0;
  for (const BenchEntry& e : a.entries)
    if (!matched.count(e.name.full)) ++onlyBefore;
  out << '\n'
      << compared << " benchmarks compared: " << significant << " significant at p < " << fmt("%g", options.alpha)
      << " (two-sided Mann-Whitney U over the repetitions), " << slower << " significantly slower by more than "
      << fmt("%g", options.regressionPercent) << "%, " << faster << " significantly faster by more than "
      << fmt("%g", options.regressionPercent) << "%; " << onlyBefore << " only before, " << onlyAfter
      << " only after.\n"
      << "Note: with 5 against 5 repetitions the smallest possible p is 2/252 = 0.0079, with 3 against 3 it is "
         "0.1 (never significant).\n";
  return slower > 0 ? 1 : 0;
}

}  // namespace reports
