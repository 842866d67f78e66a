// The cost curves: median frame time against each curve's load (lights,
// pixels, objects), whiskers from the minimum to the maximum repetition; and
// the CPU preparation curves with Google Benchmark's complexity fits.
#include "reports/bench_sections.h"
#include "reports/bench_table.h"
#include "reports/html_escape.h"
#include "reports/svg_plot.h"
#include "results/bench_names.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace reports::benchpages {

namespace bench = results::bench;
namespace {

// `e` (median, min-max whiskers) at its curve x, in the line of `group`.
void addCurvePoint(svg::SeriesBuilder& series, const std::string& group, std::size_t colourIndex,
                   const BenchEntry& e) {
  svg::Point p = svg::pointAt(*curveX(e.name.x), *e.medianMs);
  p.yLow = e.minMs;
  p.yHigh = e.maxMs;
  p.id = e.name.full;
  series.add(group, {colourIndex, true, false}, p);
}

// One line per group (backend or mode) of frame time against the curve's x.
std::string curvePlot(const BenchModel& m, const std::string& title, const std::string& scene, const Entries& entries,
                      bool byBackend) {
  svg::Plot plot;
  plot.title = title;
  plot.x = {xAxisLabel(scene), scene == "curve-lights" ? svg::Scale::Log2 : svg::Scale::Log10, false};
  double lo = INFINITY, hi = 0;
  for (const BenchEntry* e : entries) lo = std::min(lo, *e->medianMs), hi = std::max(hi, *e->medianMs);
  plot.y = {"median frame time, ms", lo > 0 && hi / lo > 20 ? svg::Scale::Log10 : svg::Scale::Linear, true};
  svg::SeriesBuilder series(plot);
  for (const BenchEntry* e : entries) {
    const std::string group = byBackend ? backendOf(*e) : e->name.mode;
    addCurvePoint(series, group, byBackend ? m.backendIndex(group) : m.modeIndex(group), *e);
  }
  svg::sortPointsByX(plot);
  return svg::render(plot);
}

std::string fitText(const ComplexityFit& fit) {
  std::string text = fit.family.mode + ": ";
  if (fit.coefficientMs) text += fmt(*fit.coefficientMs, 3) + " ms \u00b7 ";
  text += fit.bigO.empty() ? "?" : fit.bigO == "(1)" ? "1" : fit.bigO;
  if (fit.rms) text += ", RMS " + fmt(*fit.rms * 100, 3) + " %";
  return text;
}

// The dashed line of `fit` over the x range of the measured `s`; none when
// fewer than two of its points can be drawn.
std::optional<svg::Series> fitLine(const ComplexityFit& fit, const svg::Series& s) {
  svg::Series line;
  line.name = s.name + " fit " + (fit.bigO.empty() ? "?" : fit.bigO);
  line.colour = s.colour;
  line.dashed = true;
  line.markers = false;
  line.cssClass = "fit";
  const double x0 = s.points.front().x, x1 = s.points.back().x;
  for (int k = 0; k <= 40 && x1 > x0; ++k) {
    const double x = x0 * std::pow(x1 / x0, k / 40.0);
    if (const auto y = fit.at(x); y && *y > 0) line.points.push_back(svg::pointAt(x, *y));
  }
  if (line.points.size() < 2) return std::nullopt;
  return line;
}

// One prepare curve scene: its modes' lines, their fits, and the fits' list.
void prepareCurve(std::ostream& out, const BenchModel& m, const std::string& scene, const Entries& curves) {
  svg::Plot plot;
  plot.title = "prepare, " + scene;
  plot.x = {xAxisLabel(scene), svg::Scale::Log10, false};
  plot.y = {"median time, ms", svg::Scale::Log10, false};
  svg::SeriesBuilder series(plot);
  for (const BenchEntry* e : curves) addCurvePoint(series, e->name.mode, m.modeIndex(e->name.mode), *e);
  svg::sortPointsByX(plot);
  std::vector<const ComplexityFit*> fits;
  const std::size_t measured = plot.series.size();
  for (std::size_t i = 0; i < measured; ++i) {
    for (const ComplexityFit& fit : m.set.fits) {
      if (fit.family.kind != bench::kPrepare || fit.family.scene != scene || fit.family.mode != plot.series[i].name) continue;
      fits.push_back(&fit);
      if (auto line = fitLine(fit, plot.series[i])) plot.series.push_back(std::move(*line));
    }
  }
  out << "<div class=\"plotbox\">" << svg::render(plot) << "<div class=\"fits\"><strong>complexity fit</strong>";
  if (fits.empty()) out << "<p>none reported</p>";
  else {
    out << "<ul>";
    for (const ComplexityFit* f : fits) out << "<li>" << escapeText(fitText(*f)) << "</li>";
    out << "</ul>";
  }
  out << "</div></div>\n";
}

}  // namespace

void costCurveSection(std::ostream& out, const BenchModel& m, const Entries& candidates, bool byBackend) {
  const Entries curves = filter(candidates, [](const BenchEntry& e) { return e.name.kind == bench::kFrame && isCurve(e); });
  out << "<h2 id=\"curves\">Cost curves</h2>\n<p class=\"note\">Median frame time (<code>frame</code>: draw, no "
         "readback) against the load; the whiskers span the minimum and maximum over the repetitions.</p>\n";
  if (curves.empty()) {
    out << "<p>No cost-curve benchmarks.</p>\n";
    return;
  }
  for (const std::string& scene : scenesOf(curves)) {
    const Entries ofThisScene = ofScene(curves, scene);
    if (!byBackend) {
      out << curvePlot(m, scene, scene, ofThisScene, false);
      continue;
    }
    std::vector<std::string> modes;  // one plot per mode, one line per backend
    for (const BenchEntry* e : ofThisScene)
      if (std::find(modes.begin(), modes.end(), e->name.mode) == modes.end()) modes.push_back(e->name.mode);
    for (const std::string& mode : modes) {
      const Entries ofMode = filter(ofThisScene, [&](const BenchEntry& e) { return e.name.mode == mode; });
      out << curvePlot(m, scene + ", " + mode, scene, ofMode, true);
    }
  }
}

void twoTermSection(std::ostream& out, const BenchModel& m, const Entries& candidates) {
  out << "<h2 id=\"two-term\">Two-term limit</h2>\n<p class=\"note\">Each backend's frame time as a fixed cost "
         "per pixel plus a cost per pixel-light evaluation, <code>t = a \u00b7 pixels + b \u00b7 pixels \u00b7 "
         "lights_per_pixel</code>, fitted by least squares (each point weighted by 1/t\u00b2, so by its relative "
         "error) to its <code>curve-lights/all-lights</code> points; the residual is the fit's relative error at "
         "those points. The flop roof is <code>limit_ms</code>'s cost of one evaluation at the calibrated peak "
         "rate. <code>\u00d7 two-term</code> in the speed-against-error tables is each mode's median over "
         "<code>a \u00b7 pixels + b \u00b7 pixels \u00b7 lights_per_pixel</code> of its own load: near 1, the "
         "mode costs what its load predicts; above, it pays for something the two terms do not count.</p>\n";
  std::vector<std::string> shown = backendsOf(candidates);
  std::erase_if(shown, [&m](const std::string& backend) { return !m.twoTerm.contains(backend); });
  if (shown.empty()) {
    out << "<p>No backend has an all-lights light curve to fit.</p>\n";
    return;
  }
  out << "<table class=\"bench\"><tr><th>backend</th><th>points</th><th>a, ns/pixel</th><th>b, ns/pixel-light</th>"
         "<th>residual RMS %</th><th>largest residual %</th><th>flop roof, ns/pixel-light</th>"
         "<th>b / roof</th></tr>\n";
  for (const std::string& backend : shown) {
    const TwoTermFit& fit = m.twoTerm.at(backend);
    // The roof per evaluation from any curve point that carries limit_ms.
    std::optional<double> roofNs;
    for (const BenchEntry* e : candidates) {
      if (backendOf(*e) != backend || e->name.scene != "curve-lights") continue;
      const auto limit = counter(*e, bench::kLimitMs);
      const auto point = twoTermPointOf(*e);
      if (limit && point && point->pixelLights > 0) {
        roofNs = *limit / point->pixelLights * 1e6;
        break;
      }
    }
    const double bNs = fit.msPerPixelLight * 1e6;
    out << "<tr><td>" << escapeText(backend) << "</td><td>" << fit.points << "</td><td>" << fmt(fit.msPerPixel * 1e6, 3)
        << "</td><td>" << fmt(bNs, 3) << "</td><td>" << fmt(fit.rmsRelative * 100, 3) << "</td><td>"
        << fmt(fit.maxRelative * 100, 3) << "</td><td>" << fmt(roofNs, 3) << "</td><td>"
        << fmt(roofNs && *roofNs > 0 ? std::optional<double>(bNs / *roofNs) : std::nullopt, 3) << "</td></tr>\n";
  }
  out << "</table>\n";
}

void prepareSection(std::ostream& out, const BenchModel& m) {
  const Entries prepare = m.select(isPrepare);
  out << "<h2 id=\"prepare\">CPU preparation</h2>\n<p class=\"note\">Selection (SPEC 5) and packing on the CPU, "
         "log-log. Dashed: Google Benchmark's complexity fit (coefficient \u00b7 f(N), and its normalised RMS "
         "error).</p>\n";
  if (prepare.empty()) {
    out << "<p>No CPU preparation benchmarks.</p>\n";
    return;
  }
  const Entries curves = filter(prepare, isCurve);
  for (const std::string& scene : scenesOf(curves)) prepareCurve(out, m, scene, ofScene(curves, scene));
  // Fits of families that are not plotted.
  for (const ComplexityFit& fit : m.set.fits)
    if (fit.family.kind != bench::kPrepare)
      out << "<p class=\"fits\">" << escapeText(fit.family.full) << ": " << escapeText(fitText(fit)) << "</p>\n";
  out << "<h3>prepare (" << prepare.size() << ")</h3>\n";
  benchTable(out, prepare);
}

}  // namespace reports::benchpages
