#include "reports/two_term_limit.h"

#include "results/bench_names.h"

#include <algorithm>
#include <cmath>

namespace reports {

std::optional<TwoTermFit> fitTwoTerm(const std::vector<TwoTermPoint>& points) {
  if (points.size() < 2) return std::nullopt;
  // Normal equations of min sum w (t - a P - b L)^2, w = 1 / t^2.
  double s11 = 0, s12 = 0, s22 = 0, r1 = 0, r2 = 0;
  for (const TwoTermPoint& p : points) {
    if (!(p.ms > 0) || !(p.pixels > 0) || !std::isfinite(p.pixelLights)) return std::nullopt;
    const double w = 1.0 / (p.ms * p.ms);
    s11 += w * p.pixels * p.pixels;
    s12 += w * p.pixels * p.pixelLights;
    s22 += w * p.pixelLights * p.pixelLights;
    r1 += w * p.pixels * p.ms;
    r2 += w * p.pixelLights * p.ms;
  }
  const double det = s11 * s22 - s12 * s12;
  // Singular (up to rounding) when every point has the same lights per pixel.
  if (!(std::abs(det) > 1e-12 * s11 * s22)) return std::nullopt;
  TwoTermFit fit;
  fit.msPerPixel = (r1 * s22 - r2 * s12) / det;
  fit.msPerPixelLight = (s11 * r2 - s12 * r1) / det;
  fit.points = int(points.size());
  double sumSquares = 0;
  for (const TwoTermPoint& p : points) {
    const double relative = (p.ms - fit.estimateMs(p.pixels, p.pixelLights)) / p.ms;
    sumSquares += relative * relative;
    fit.maxRelative = std::max(fit.maxRelative, std::abs(relative));
  }
  fit.rmsRelative = std::sqrt(sumSquares / double(points.size()));
  return fit;
}

std::optional<TwoTermPoint> twoTermPointOf(const BenchEntry& e) {
  const auto pixels = e.counters.find(std::string(results::bench::kPixels));
  const auto lights = e.counters.find(std::string(results::bench::kLightsPerPixel));
  if (pixels == e.counters.end() || lights == e.counters.end() || !e.medianMs) return std::nullopt;
  return TwoTermPoint{pixels->second, pixels->second * lights->second, *e.medianMs};
}

std::map<std::string, TwoTermFit> twoTermFits(const BenchSet& set) {
  std::map<std::string, std::vector<TwoTermPoint>> curves;
  for (const BenchEntry& e : set.entries) {
    if (e.name.kind != results::bench::kFrame || e.name.scene != "curve-lights" || e.name.mode != "all-lights" || !e.error.empty())
      continue;
    if (const auto point = twoTermPointOf(e)) curves[e.section.empty() ? e.name.backend : e.section].push_back(*point);
  }
  std::map<std::string, TwoTermFit> fits;
  for (const auto& [backend, points] : curves)
    if (const auto fit = fitTwoTerm(points)) fits.emplace(backend, *fit);
  return fits;
}

}  // namespace reports
