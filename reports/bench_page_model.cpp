#include "reports/bench_page_model.h"

#include "reports/bench_report.h"
#include "results/bench_names.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string_view>

namespace reports::benchpages {

namespace bench = results::bench;

BenchModel::BenchModel(const Json& b)
    : bench(b), set(readBenchFile(b)), backends(benchBackends(b)), twoTerm(twoTermFits(set)) {
  for (const BenchEntry& e : set.entries)
    if (!e.name.mode.empty() && std::find(modes.begin(), modes.end(), e.name.mode) == modes.end())
      modes.push_back(e.name.mode);
}

std::size_t BenchModel::backendIndex(const std::string& name) const {
  return std::size_t(std::find(backends.begin(), backends.end(), name) - backends.begin());
}

std::size_t BenchModel::modeIndex(const std::string& name) const {
  return std::size_t(std::find(modes.begin(), modes.end(), name) - modes.begin());
}

Entries BenchModel::select(const Keep& keep) const {
  Entries all;
  for (const BenchEntry& e : set.entries) all.push_back(&e);
  return filter(all, keep);
}

Entries filter(const Entries& entries, const Keep& keep) {
  Entries out;
  for (const BenchEntry* e : entries)
    if (keep(*e)) out.push_back(e);
  return out;
}

Entries ofScene(const Entries& entries, const std::string& scene) {
  return filter(entries, [&](const BenchEntry& e) { return e.name.scene == scene; });
}

std::string fmt(double v, int digits) {
  if (!std::isfinite(v)) return "-";
  char text[40];
  if (v == std::floor(v) && std::abs(v) < 1e7) std::snprintf(text, sizeof text, "%.0f", v);
  else std::snprintf(text, sizeof text, "%.*g", digits, v);
  return text;
}

std::string fmt(const std::optional<double>& v, int digits) { return v ? fmt(*v, digits) : "-"; }

std::optional<double> counter(const BenchEntry& e, std::string_view key) {
  const auto it = e.counters.find(std::string(key));
  if (it == e.counters.end()) return std::nullopt;
  return it->second;
}

std::optional<double> twoTermRatio(const BenchModel& m, const BenchEntry& e) {
  const auto fit = m.twoTerm.find(backendOf(e));
  const auto point = twoTermPointOf(e);
  if (fit == m.twoTerm.end() || !point) return std::nullopt;
  const double estimate = fit->second.estimateMs(point->pixels, point->pixelLights);
  if (!(estimate > 0)) return std::nullopt;
  return point->ms / estimate;
}

std::optional<double> limitRatio(const BenchEntry& e) {
  const auto limit = counter(e, bench::kLimitMs);
  if (!limit || !(*limit > 0) || !e.medianMs) return std::nullopt;
  return *e.medianMs / *limit;
}

std::string backendOf(const BenchEntry& e) { return e.section.empty() ? e.name.backend : e.section; }

std::vector<std::string> backendsOf(const Entries& entries) {
  std::vector<std::string> backends;
  for (const BenchEntry* e : entries)
    if (std::find(backends.begin(), backends.end(), backendOf(*e)) == backends.end()) backends.push_back(backendOf(*e));
  return backends;
}

bool isPrepare(const BenchEntry& e) { return e.name.kind == bench::kPrepare; }

bool isBroken(const BenchEntry& e) {
  const auto pixels = counter(e, bench::kErrNonfinitePixels);
  return pixels && *pixels > 0;
}

bool hasError(const BenchEntry& e) {
  const auto rmse = counter(e, bench::kErrRmse);
  return e.name.kind == bench::kFrame && e.medianMs && rmse && std::isfinite(*rmse) && !isBroken(e);
}

std::optional<double> lightmapResolution(const BenchEntry& e) {
  constexpr std::string_view prefix = "lightmap-";
  if (e.name.mode.rfind(prefix, 0) != 0) return std::nullopt;
  const auto n = curveX(std::string_view(e.name.mode).substr(prefix.size()));
  if (!n || *n < 1 || e.name.mode.find('x', prefix.size()) != std::string::npos) return std::nullopt;
  return n;
}

bool isCurve(const BenchEntry& e) {
  return e.name.scene.rfind("curve-", 0) == 0 && curveX(e.name.x).has_value() && e.medianMs.has_value();
}

std::vector<std::string> scenesOf(const Entries& entries) {
  std::vector<std::string> scenes;
  for (const BenchEntry* e : entries)
    if (std::find(scenes.begin(), scenes.end(), e->name.scene) == scenes.end()) scenes.push_back(e->name.scene);
  std::stable_sort(scenes.begin(), scenes.end(), [](const std::string& a, const std::string& b) {
    const auto rank = [](const std::string& s) {
      if (s == "lights64-1280x720") return 0;
      if (s.rfind("dense64-", 0) == 0) return 1;
      if (s.rfind("meshes64-", 0) == 0) return 2;
      if (s.rfind("lightmap-", 0) == 0) return 3;
      if (s == "curve-lights") return 4;
      if (s == "curve-resolution") return 5;
      if (s == "curve-objects") return 6;
      return 7;
    };
    return rank(a) < rank(b);
  });
  return scenes;
}

std::string xAxisLabel(const std::string& scene) {
  if (scene == "curve-lights") return "lights";
  if (scene == "curve-resolution") return "pixels";
  if (scene == "curve-objects") return "objects";
  if (scene == "curve-lightmap") return "lightmap texels";
  if (scene == "curve-cluster-tile") return "tile side (pixels)";
  return scene.substr(6);
}

}  // namespace reports::benchpages
