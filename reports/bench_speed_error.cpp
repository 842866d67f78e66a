// Speed against error: one point per (backend, mode) of the `frame`
// benchmarks, median frame time against err_rmse, the Pareto front ringed
// and joined by steps, and the table of the points in time order. A broken
// mode (NaN or infinite pixels: isBroken) is no point and never on the
// front: it is listed after the points, marked broken.
#include "reports/bench_report.h"
#include "reports/bench_sections.h"
#include "reports/bench_table.h"
#include "reports/html_escape.h"
#include "reports/svg_plot.h"
#include "results/bench_names.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numeric>
#include <utility>

namespace reports {

namespace bench = results::bench;

std::vector<bool> paretoFront(const std::vector<std::pair<double, double>>& points) {
  std::vector<bool> front(points.size(), true);
  for (std::size_t i = 0; i < points.size(); ++i)
    for (std::size_t j = 0; j < points.size() && front[i]; ++j) {
      const auto& [ti, ei] = points[i];
      const auto& [tj, ej] = points[j];
      if (j != i && tj <= ti && ej <= ei && (tj < ti || ej < ei)) front[i] = false;
    }
  return front;
}

namespace benchpages {
namespace {

using TimeError = std::pair<double, double>;

// Log10 errors when they span more than a decade and are all positive.
svg::Scale errorScale(const std::vector<TimeError>& te) {
  double lo = INFINITY, hi = 0;
  for (const auto& [t, err] : te)
    if (err > 0) lo = std::min(lo, err), hi = std::max(hi, err);
  const bool positive = std::all_of(te.begin(), te.end(), [](const TimeError& p) { return p.second > 0; });
  return lo > 0 && hi / lo > 10 && positive ? svg::Scale::Log10 : svg::Scale::Linear;
}

// An error for a hover title: three significant digits ("1.23e-05").
std::string errorText(double error) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", error);
  return text;
}

// The front as one stepped line in time order, drawn under the points.
svg::Series frontLine(const std::vector<TimeError>& te, const std::vector<bool>& front) {
  svg::Series line;
  line.name = "Pareto front";
  line.colour = "#000";
  line.markers = false;
  line.steps = true;
  line.cssClass = "front";
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < te.size(); ++i)
    if (front[i]) order.push_back(i);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return te[a] < te[b]; });
  for (std::size_t i : order) line.points.push_back(svg::pointAt(te[i].first, te[i].second));
  return line;
}

// The columns of the Pareto table; `onFront` says which rows are on it.
Table<const BenchEntry*> paretoTable(const BenchModel& m, const std::map<const BenchEntry*, bool>& onFront,
                                     bool withBake, bool withShadowPasses) {
  Table<const BenchEntry*> table;
  table.cssClass = "bench pareto";
  const auto front = [&onFront](const BenchEntry& e) { return onFront.at(&e); };
  table.rowClass = [front](const BenchEntry* e) {
    return std::string(isBroken(*e) ? "broken" : front(*e) ? "front" : "");
  };
  table.columns = {
      textColumn("backend", backendOf),
      markedTextColumn("mode", [](const BenchEntry& e) { return e.name.mode; }),
      textColumn("Pareto front",
                 [front](const BenchEntry& e) {
                   return std::string(isBroken(e) ? "no: broken" : front(e) ? "yes" : "");
                 }),
      numberColumn("median ms", [](const BenchEntry& e) { return e.medianMs; }),
      cpuColumn(),
      numberColumn("min ms", [](const BenchEntry& e) { return e.minMs; }),
      numberColumn("max ms", [](const BenchEntry& e) { return e.maxMs; }),
      cvColumn(),
      numberColumn("n", [](const BenchEntry& e) { return std::optional<double>(e.count); }),
      counterColumn("err_rmse", bench::kErrRmse),
      counterColumn("err_max_abs", bench::kErrMaxAbs),
      counterColumn("err_psnr_db", bench::kErrPsnrDb),
  };
  // The lightmap modes carry their bake time: the price paid before the frame.
  if (withBake) table.columns.push_back(counterColumn("bake ms", bench::kBakeMs));
  // The shadow-map modes carry their shadow passes' share of the frame.
  if (withShadowPasses) table.columns.push_back(counterColumn("shadow pass ms", bench::kShadowPassMs));
  table.columns.push_back(numberColumn("\u00d7 limit", limitRatio, 3));
  // The time over the backend's two-term estimate for the mode's load.
  table.columns.push_back(
      numberColumn("\u00d7 two-term", [&m](const BenchEntry& e) { return twoTermRatio(m, e); }, 3));
  return table;
}

// The scatter of one scene and its table; colours by backend (overview) or
// by mode (a backend page). `broken`: the scene's broken modes, table rows only.
void scatterSection(std::ostream& out, const BenchModel& m, const std::string& scene, const Entries& points,
                    const Entries& broken, bool byBackend) {
  std::vector<TimeError> te;
  for (const BenchEntry* e : points) te.emplace_back(*e->medianMs, *counter(*e, bench::kErrRmse));
  const std::vector<bool> front = paretoFront(te);
  out << "<h3>" << escapeText(scene) << "</h3>\n";

  svg::Plot plot;
  plot.title = scene + ": speed against error (frame)";
  plot.x = {"median frame time, ms", svg::Scale::Log10, false};
  plot.y = {"err_rmse against --ideal", errorScale(te), true};
  svg::SeriesBuilder series(plot);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const BenchEntry& e = *points[i];
    const std::string group = byBackend ? backendOf(e) : e.name.mode;
    svg::Point p = svg::pointAt(te[i].first, te[i].second);
    p.id = backendOf(e) + "/" + e.name.mode;
    p.title = e.name.mode + " on " + backendOf(e) + ": median " + svg::tickText(te[i].first) + " ms, err_rmse " +
              errorText(te[i].second) + (front[i] ? " (Pareto front)" : "");
    p.label = e.name.mode;
    p.highlight = front[i];
    if (e.count >= 2 && e.minMs && e.maxMs) p.xLow = e.minMs, p.xHigh = e.maxMs;  // the repetitions' spread
    series.add(group, {byBackend ? m.backendIndex(group) : m.modeIndex(group), false, false}, p);
  }
  plot.series.insert(plot.series.begin(), frontLine(te, front));
  if (!points.empty()) out << svg::render(plot);

  std::map<const BenchEntry*, bool> onFront;
  for (std::size_t i = 0; i < points.size(); ++i) onFront[points[i]] = front[i];
  for (const BenchEntry* e : broken) onFront[e] = false;
  const auto bakes = [](const BenchEntry* e) { return counter(*e, bench::kBakeMs).has_value(); };
  const bool withBake =
      std::any_of(points.begin(), points.end(), bakes) || std::any_of(broken.begin(), broken.end(), bakes);
  const auto shadowPasses = [](const BenchEntry* e) { return counter(*e, bench::kShadowPassMs).has_value(); };
  const bool withShadowPasses = std::any_of(points.begin(), points.end(), shadowPasses) ||
                                std::any_of(broken.begin(), broken.end(), shadowPasses);
  std::vector<std::size_t> order(points.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return te[a] < te[b]; });
  Entries rows;
  for (std::size_t i : order) rows.push_back(points[i]);
  Entries brokenRows = broken;  // after the points, in time order
  std::stable_sort(brokenRows.begin(), brokenRows.end(),
                   [](const BenchEntry* a, const BenchEntry* b) { return *a->medianMs < *b->medianMs; });
  rows.insert(rows.end(), brokenRows.begin(), brokenRows.end());
  writeTable(out, paretoTable(m, onFront, withBake, withShadowPasses), rows);
}

bool isShadowMapMode(const BenchEntry& e) { return e.name.kind == bench::kFrame && e.name.mode.rfind("shadows-", 0) == 0; }

}  // namespace

void speedErrorSection(std::ostream& out, const BenchModel& m, const Entries& candidates, bool byBackend) {
  out << "<h2 id=\"pareto\">Speed against error</h2>\n<p class=\"note\">One point per (backend, mode) of the "
         "<code>frame</code> benchmarks: median frame time against the RMS error of the image against the "
         "<code>--ideal</code> reference. Ringed points, joined by the black steps, are the Pareto front: no other "
         "point is both faster and more accurate. A mode whose image has NaN or infinite pixels "
         "(<code>err_nonfinite_pixels</code> &gt; 0) is broken: it has no error, is no point and never on the "
         "front, and is listed, marked broken, after the points of its scene.</p>\n";
  const Entries withError = filter(candidates, hasError);
  const Entries broken =
      filter(candidates, [](const BenchEntry& e) { return e.name.kind == bench::kFrame && e.medianMs && isBroken(e); });
  if (withError.empty() && broken.empty()) {
    out << "<p>No frame benchmark has error counters.</p>\n";
    return;
  }
  Entries all = withError;
  all.insert(all.end(), broken.begin(), broken.end());
  for (const std::string& scene : scenesOf(all))
    scatterSection(out, m, scene, ofScene(withError, scene), ofScene(broken, scene), byBackend);
}

void shadowMapSection(std::ostream& out, const BenchModel& m, const Entries& candidates) {
  const Entries shadowModes = filter(candidates, isShadowMapMode);
  if (shadowModes.empty()) return;
  out << "<h2 id=\"shadow-maps\">Shadow maps: resolution and filter</h2>\n<p class=\"note\">SPEC 3.9's "
         "shadow maps at 256 to 4096 texels with each filter (<code>shadows-&lt;filter&gt;-&lt;N&gt;</code>: a "
         "directional light, two spots and a point light casting onto the field's boxes), per backend: median frame "
         "time against the RMS error of the image against <code>--ideal</code>, whose shadows are ray-traced, so "
         "the error is what a map's resolution and filter cost against exact shadows. The front is what is worth "
         "choosing; <code>shadow pass ms</code> is the shadow passes' share of the frame, timed apart. "
         "<code>shadow-lights</code>, the same lights casting nothing, is on the scatter above.</p>\n";
  const std::vector<std::string> backends = backendsOf(shadowModes);
  for (const std::string& backend : backends) {
    const Entries mine = filter(shadowModes, [&](const BenchEntry& e) { return backendOf(e) == backend; });
    const Entries withError = filter(mine, hasError);
    const Entries broken = filter(mine, [](const BenchEntry& e) { return e.medianMs && isBroken(e); });
    scatterSection(out, m, scenesOf(mine).front() + " shadow maps on " + backend, withError, broken, false);
  }
}

}  // namespace benchpages
}  // namespace reports
