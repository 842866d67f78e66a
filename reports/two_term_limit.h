// The two-term limit: a backend's frame time modelled as a fixed
// cost per pixel plus a cost per pixel-light evaluation,
//   t = a * pixels + b * pixels * lights_per_pixel,
// fitted by least squares to its all-lights light-count curve
// (frame/<backend>/curve-lights/all-lights/<n>: the same pixels, evaluations
// growing with the kept lights), with the fit's residual. Beside the flop
// roof (limit_ms, which counts only the arithmetic of each evaluation) it
// says whether a mode is bound by per-pixel overhead (rasterisation, the
// G-buffer, the target's bandwidth: a) or by light evaluation (b), and each
// mode's time over its own two-term estimate says how far it is from what
// this backend's curve predicts for its load.
#pragma once

#include "reports/bench_data.h"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace reports {

struct TwoTermPoint {
  double pixels = 0;
  double pixelLights = 0;  // pixels * lights_per_pixel
  double ms = 0;
};

struct TwoTermFit {
  double msPerPixel = 0;       // a
  double msPerPixelLight = 0;  // b
  // Residuals relative to each point's time, (t - fit) / t: their root mean
  // square and their largest magnitude.
  double rmsRelative = 0;
  double maxRelative = 0;
  int points = 0;
  double estimateMs(double pixels, double pixelLights) const { return msPerPixel * pixels + msPerPixelLight * pixelLights; }
};

// Weighted least squares with weights 1 / t^2, so every point counts by its
// relative error (a curve spans two decades of time; unweighted, the
// slowest point would decide alone). nullopt with fewer than two points, a
// point without a positive time, or when pixelLights / pixels is the same
// at every point (the two terms cannot be told apart).
std::optional<TwoTermFit> fitTwoTerm(const std::vector<TwoTermPoint>& points);

// The points of each backend's all-lights light curve in `set`, and their fits.
std::map<std::string, TwoTermFit> twoTermFits(const BenchSet& set);

// An entry's load as the fit reads it: nullopt without pixels and
// lights_per_pixel counters.
std::optional<TwoTermPoint> twoTermPointOf(const BenchEntry& e);

}  // namespace reports
