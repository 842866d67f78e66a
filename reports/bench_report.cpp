#include "reports/bench_report.h"

#include "imaging/text_file.h"
#include "reports/bench_data.h"
#include "reports/html_escape.h"
#include "reports/result_fields.h"
#include "reports/svg_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string_view>

namespace reports {
namespace {

namespace fs = std::filesystem;

constexpr const char* kStyle = R"(
body { font: 14px/1.4 system-ui, sans-serif; margin: 1.5em; color: #222; }
h1 { font-size: 1.5em; } h2 { border-bottom: 1px solid #ccc; margin-top: 2em; } h3 { margin-bottom: .3em; }
nav a { margin-right: 1em; }
table { border-collapse: collapse; margin: .5em 0; }
th, td { border: 1px solid #ccc; padding: 2px 6px; text-align: left; vertical-align: top; }
th { background: #f3f3f3; } td.n { text-align: right; font-variant-numeric: tabular-nums; }
table.bench { font-size: .85em; }
dl.meta { display: grid; grid-template-columns: max-content auto; gap: 2px 1em; }
dl.meta dt { font-weight: bold; } dl.meta dd { margin: 0; }
svg.plot { max-width: 100%; height: auto; border: 1px solid #ddd; display: block; margin: .5em 0; }
.plotbox { display: flex; flex-wrap: wrap; align-items: flex-start; gap: 1em; }
.fits { font-size: .9em; }
tr.front td:first-child, tr.front td:nth-child(2) { font-weight: bold; }
.err { color: #b00; } .note { color: #555; font-size: .9em; }
)";

using Entries = std::vector<const BenchEntry*>;

std::string fmt(double v, int digits = 4) {
  if (!std::isfinite(v)) return "-";
  char text[40];
  if (v == std::floor(v) && std::abs(v) < 1e7) std::snprintf(text, sizeof text, "%.0f", v);  // 921600, not 9.216e+05
  else std::snprintf(text, sizeof text, "%.*g", digits, v);
  return text;
}
std::string fmt(const std::optional<double>& v, int digits = 4) { return v ? fmt(*v, digits) : "-"; }

std::optional<double> counter(const BenchEntry& e, const std::string& key) {
  const auto it = e.counters.find(key);
  if (it == e.counters.end()) return std::nullopt;
  return it->second;
}

std::optional<double> limitRatio(const BenchEntry& e) {
  const auto limit = counter(e, "limit_ms");
  if (!limit || !(*limit > 0) || !e.medianMs) return std::nullopt;
  return *e.medianMs / *limit;
}

std::string backendOf(const BenchEntry& e) { return e.section.empty() ? e.name.backend : e.section; }

// Everything the pages need, read once.
struct Model {
  const Json& bench;
  BenchSet set;
  std::vector<std::string> backends;  // page order and colours
  std::vector<std::string> modes;     // colour order on backend pages

  explicit Model(const Json& b) : bench(b), set(readBenchFile(b)), backends(benchBackends(b)) {
    for (const BenchEntry& e : set.entries)
      if (!e.name.mode.empty() && std::find(modes.begin(), modes.end(), e.name.mode) == modes.end())
        modes.push_back(e.name.mode);
  }
  std::size_t backendIndex(const std::string& name) const {
    return std::size_t(std::find(backends.begin(), backends.end(), name) - backends.begin());
  }
  std::size_t modeIndex(const std::string& name) const {
    return std::size_t(std::find(modes.begin(), modes.end(), name) - modes.begin());
  }
  Entries select(const std::function<bool(const BenchEntry&)>& keep) const {
    Entries out;
    for (const BenchEntry& e : set.entries)
      if (keep(e)) out.push_back(&e);
    return out;
  }
};

svg::Point plainPoint(double x, double y) {
  svg::Point p;
  p.x = x;
  p.y = y;
  return p;
}

bool isPrepare(const BenchEntry& e) { return e.name.kind == "prepare"; }
bool hasError(const BenchEntry& e) { return e.name.kind == "frame" && e.medianMs && counter(e, "err_rmse"); }
// N of a `lightmap-N` mode (docs/bench-format.md); nullopt for other modes.
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

// Scenes in first-appearance order, the synthetic lights64-1280x720 first.
std::vector<std::string> scenesOf(const Entries& entries) {
  std::vector<std::string> scenes;
  for (const BenchEntry* e : entries)
    if (std::find(scenes.begin(), scenes.end(), e->name.scene) == scenes.end()) scenes.push_back(e->name.scene);
  std::stable_sort(scenes.begin(), scenes.end(), [](const std::string& a, const std::string& b) {
    const auto rank = [](const std::string& s) {
      if (s == "lights64-1280x720") return 0;
      if (s.rfind("lightmap-", 0) == 0) return 1;
      if (s == "curve-lights") return 2;
      if (s == "curve-resolution") return 3;
      if (s == "curve-objects") return 4;
      return 5;
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
  return scene.substr(6);
}

// ---- page frame ----------------------------------------------------------

void pageStart(std::ostringstream& out, const Model& m, const std::string& title, const std::string& current) {
  out << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" << escapeText(title)
      << "</title>\n<style>" << kStyle << "</style>\n</head>\n<body>\n<h1>" << escapeText(title) << "</h1>\n<nav>";
  out << (current.empty() ? "<strong>overview</strong>" : "<a href=\"index.html\">overview</a>") << ' ';
  for (const std::string& b : m.backends) {
    if (b == current) out << "<strong>" << escapeText(b) << "</strong>";
    else out << "<a href=\"" << escapeText(percentEncodePath(benchPageFile(b))) << "\">" << escapeText(b) << "</a>";
    out << ' ';
  }
  out << "</nav>\n";
}

void metaRow(std::ostringstream& out, const std::string& key, const std::string& value) {
  if (value.empty()) return;
  out << "<dt>" << escapeText(key) << "</dt><dd>" << escapeText(value) << "</dd>\n";
}

void runMeta(std::ostringstream& out, const Model& m) {
  const Json& b = m.bench;
  const Json& machine = objectField(b, "machine");
  const Json& peak = objectField(b, "peak");
  out << "<h2 id=\"run\">Run</h2>\n<dl class=\"meta\">\n";
  metaRow(out, "revision", textField(b, "lightcts_revision"));
  metaRow(out, "started (UTC)", textField(b, "started_utc"));
  if (const auto d = numberField(b, "duration_s")) metaRow(out, "duration", formatSeconds(*d) + " s");
  metaRow(out, "command", textField(b, "command"));
  metaRow(out, "machine", textField(machine, "hostname"));
  metaRow(out, "cpu", textField(machine, "cpu"));
  metaRow(out, "cores", textField(machine, "cores"));
  metaRow(out, "os", textField(machine, "os"));
  if (const auto g = numberField(peak, "gflops")) {
    std::string text = fmt(*g) + " GFLOP/s";
    if (const auto c = textField(peak, "cores"); !c.empty()) text += " on " + c + " cores";
    if (const auto n = textField(peak, "median_of"); !n.empty()) text += ", median of " + n;
    if (const auto k = textField(peak, "kernel"); !k.empty()) text += " (" + k + ")";
    metaRow(out, "peak rate", text);
  }
  out << "</dl>\n";
}

const Json& backendJson(const Json& bench, const std::string& backend) {
  static const Json none = Json::object();
  for (const Json& b : arrayField(bench, "backends"))
    if (textField(b, "backend") == backend) return b;
  return none;
}

// ---- tables ----------------------------------------------------------------

struct Column {
  std::string head;
  std::function<std::optional<double>(const BenchEntry&)> value;
  int digits = 4;
};

std::vector<Column> allColumns(const Entries& entries) {
  std::vector<Column> columns = {
      {"median ms", [](const BenchEntry& e) { return e.medianMs; }},
      {"min ms", [](const BenchEntry& e) { return e.minMs; }},
      {"max ms", [](const BenchEntry& e) { return e.maxMs; }},
      {"stddev ms", [](const BenchEntry& e) { return e.stddevMs; }, 3},
      {"n", [](const BenchEntry& e) { return e.count ? std::optional<double>(e.count) : std::nullopt; }},
  };
  const std::vector<std::pair<std::string, std::string>> known = {
      {"wall_ms", "wall ms"}, {"device_ms", "device ms"}, {"pixels", "pixels"}, {"lights", "lights"},
      {"lights_per_pixel", "lights/pixel"}, {"pixels_per_s", "pixels/s"},
      {"pixel_light_evals_per_s", "pixel-light evals/s"}, {"err_rmse", "err_rmse"},
      {"err_max_abs", "err_max_abs"}, {"err_psnr_db", "err_psnr_db"},
      {"err_perceptual_fail", "err_perceptual_fail"}, {"bake_ms", "bake ms"}, {"bake_runs", "bake runs"},
      {"lightmap_texels", "lightmap texels"}, {"flops_per_pixel_light", "flops/pixel-light"},
      {"limit_ms", "limit ms"}};
  for (const auto& [key, head] : known)
    columns.push_back({head, [key = key](const BenchEntry& e) { return counter(e, key); }});
  columns.push_back({"\u00d7 limit", limitRatio, 3});
  std::set<std::string> seen;
  for (const auto& [key, head] : known) seen.insert(key);
  for (const BenchEntry* e : entries)
    for (const auto& [key, value] : e->counters)
      if (seen.insert(key).second)
        columns.push_back({key, [key = key](const BenchEntry& x) { return counter(x, key); }});
  // Only the columns that some row has.
  std::vector<Column> used;
  for (Column& c : columns)
    if (std::any_of(entries.begin(), entries.end(), [&](const BenchEntry* e) { return c.value(*e).has_value(); }))
      used.push_back(std::move(c));
  return used;
}

void benchTable(std::ostringstream& out, const Entries& entries) {
  if (entries.empty()) return;
  const std::vector<Column> columns = allColumns(entries);
  out << "<table class=\"bench\">\n<tr><th>benchmark</th>";
  for (const Column& c : columns) out << "<th>" << escapeText(c.head) << "</th>";
  out << "</tr>\n";
  for (const BenchEntry* e : entries) {
    out << "<tr><td>" << escapeText(e->name.full) << "</td>";
    if (!e->error.empty() && !e->medianMs) {
      out << "<td class=\"err\" colspan=\"" << columns.size() << "\">error: " << escapeText(e->error) << "</td>";
    } else {
      for (const Column& c : columns) out << "<td class=\"n\">" << fmt(c.value(*e), c.digits) << "</td>";
    }
    out << "</tr>\n";
  }
  out << "</table>\n";
}

void tablesByKind(std::ostringstream& out, const Entries& entries) {
  std::vector<std::string> kinds;
  for (const BenchEntry* e : entries)
    if (std::find(kinds.begin(), kinds.end(), e->name.kind) == kinds.end()) kinds.push_back(e->name.kind);
  for (const std::string& kind : kinds) {
    Entries ofKind;
    for (const BenchEntry* e : entries)
      if (e->name.kind == kind) ofKind.push_back(e);
    out << "<h3>" << escapeText(kind) << " (" << ofKind.size() << ")</h3>\n";
    benchTable(out, ofKind);
  }
}

// ---- plots -----------------------------------------------------------------

// The speed-against-error scatter of one scene and its table; colours by
// backend (overview) or by mode (a backend page).
void scatterSection(std::ostringstream& out, const Model& m, const std::string& scene, const Entries& points,
                    bool byBackend) {
  std::vector<std::pair<double, double>> te;
  for (const BenchEntry* e : points) te.emplace_back(*e->medianMs, *counter(*e, "err_rmse"));
  const std::vector<bool> front = paretoFront(te);

  svg::Plot plot;
  plot.title = scene + ": speed against error (frame)";
  plot.x = {"median frame time, ms", svg::Scale::Log10, false};
  double lo = INFINITY, hi = 0;
  for (const auto& [t, err] : te)
    if (err > 0) lo = std::min(lo, err), hi = std::max(hi, err);
  const bool logY = lo > 0 && hi / lo > 10 &&
                    std::all_of(te.begin(), te.end(), [](const auto& p) { return p.second > 0; });
  plot.y = {"err_rmse against --ideal", logY ? svg::Scale::Log10 : svg::Scale::Linear, true};

  std::map<std::string, std::size_t> seriesOf;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const BenchEntry& e = *points[i];
    const std::string group = byBackend ? backendOf(e) : e.name.mode;
    auto [it, added] = seriesOf.emplace(group, plot.series.size());
    if (added) {
      svg::Series s;
      s.name = group;
      s.colour = svg::colour(byBackend ? m.backendIndex(group) : m.modeIndex(group));
      s.line = false;
      plot.series.push_back(s);
    }
    svg::Point p;
    p.x = te[i].first;
    p.y = te[i].second;
    p.id = backendOf(e) + "/" + e.name.mode;
    p.label = e.name.mode;
    p.highlight = front[i];
    plot.series[it->second].points.push_back(p);
  }
  svg::Series frontLine;
  frontLine.name = "Pareto front";
  frontLine.colour = "#000";
  frontLine.markers = false;
  frontLine.steps = true;
  frontLine.cssClass = "front";
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < te.size(); ++i)
    if (front[i]) order.push_back(i);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return te[a] < te[b]; });
  for (std::size_t i : order) frontLine.points.push_back(plainPoint(te[i].first, te[i].second));
  plot.series.insert(plot.series.begin(), frontLine);  // drawn under the points

  // The lightmap modes carry their bake time: the price paid before the frame.
  const bool withBake =
      std::any_of(points.begin(), points.end(), [](const BenchEntry* e) { return counter(*e, "bake_ms").has_value(); });
  out << "<h3>" << escapeText(scene) << "</h3>\n" << svg::render(plot);
  out << "<table class=\"bench pareto\">\n<tr><th>backend</th><th>mode</th><th>Pareto front</th><th>median ms</th>"
         "<th>min ms</th><th>max ms</th><th>n</th><th>err_rmse</th><th>err_max_abs</th><th>err_psnr_db</th>"
      << (withBake ? "<th>bake ms</th>" : "") << "<th>\u00d7 limit</th></tr>\n";
  std::vector<std::size_t> rows(points.size());
  for (std::size_t i = 0; i < rows.size(); ++i) rows[i] = i;
  std::stable_sort(rows.begin(), rows.end(), [&](std::size_t a, std::size_t b) { return te[a] < te[b]; });
  for (std::size_t i : rows) {
    const BenchEntry& e = *points[i];
    out << "<tr" << (front[i] ? " class=\"front\"" : "") << "><td>" << escapeText(backendOf(e)) << "</td><td>"
        << escapeText(e.name.mode) << "</td><td>" << (front[i] ? "yes" : "") << "</td><td class=\"n\">"
        << fmt(e.medianMs) << "</td><td class=\"n\">" << fmt(e.minMs) << "</td><td class=\"n\">" << fmt(e.maxMs)
        << "</td><td class=\"n\">" << e.count << "</td><td class=\"n\">" << fmt(counter(e, "err_rmse"))
        << "</td><td class=\"n\">" << fmt(counter(e, "err_max_abs")) << "</td><td class=\"n\">"
        << fmt(counter(e, "err_psnr_db")) << "</td>";
    if (withBake) out << "<td class=\"n\">" << fmt(counter(e, "bake_ms")) << "</td>";
    out << "<td class=\"n\">" << fmt(limitRatio(e), 3) << "</td></tr>\n";
  }
  out << "</table>\n";
}

void speedErrorSection(std::ostringstream& out, const Model& m, const Entries& candidates, bool byBackend) {
  out << "<h2 id=\"pareto\">Speed against error</h2>\n<p class=\"note\">One point per (backend, mode) of the "
         "<code>frame</code> benchmarks: median frame time against the RMS error of the image against the "
         "<code>--ideal</code> reference. Ringed points, joined by the black steps, are the Pareto front: no other "
         "point is both faster and more accurate.</p>\n";
  const Entries withError = [&] {
    Entries e;
    for (const BenchEntry* x : candidates)
      if (hasError(*x)) e.push_back(x);
    return e;
  }();
  if (withError.empty()) {
    out << "<p>No frame benchmark has error counters.</p>\n";
    return;
  }
  for (const std::string& scene : scenesOf(withError)) {
    Entries points;
    for (const BenchEntry* e : withError)
      if (e->name.scene == scene) points.push_back(e);
    scatterSection(out, m, scene, points, byBackend);
  }
}

// A line of `plot` per group, started in colour `colourIndex` the first time.
svg::Series& lineOf(svg::Plot& plot, std::map<std::string, std::size_t>& seriesOf, const std::string& group,
                    std::size_t colourIndex, bool dashed) {
  auto [it, added] = seriesOf.emplace(group, plot.series.size());
  if (added) {
    svg::Series s;
    s.name = group;
    s.colour = svg::colour(colourIndex);
    s.dashed = dashed;
    plot.series.push_back(s);
  }
  return plot.series[it->second];
}

// The `lightmap-N` modes (docs/bench-format.md) against N: the error of the
// baked image against the same lights in real time, and the bake time
// beside the frame time; one line per backend (overview) or per quantity (a
// backend page), then the table with the scene's `realtime` point for
// comparison. Nothing when no lightmap mode ran.
void lightmapSection(std::ostringstream& out, const Model& m, const Entries& candidates, bool byBackend) {
  Entries maps;
  for (const BenchEntry* e : candidates)
    if (e->name.kind == "frame" && e->medianMs && lightmapResolution(*e)) maps.push_back(e);
  if (maps.empty()) return;
  out << "<h2 id=\"lightmap\">Lightmap resolution</h2>\n<p class=\"note\">The <code>lightmap-N</code> modes: the "
         "scene's lights baked into an N \u00d7 N lightmap (SPEC 3.6), drawn and compared with the "
         "<code>--ideal</code> reference of the same lights lit in real time, so the error is what the bake loses "
         "(resolution, bilinear filtering, and the baked shadow that real time does not draw). The bake time is the "
         "median of fresh bakes (no cache, every core) of that process; the frame time is the median draw "
         "(<code>frame</code>). The <code>realtime</code> row is the same lights lit per pixel, against the same "
         "reference.</p>\n";
  for (const std::string& scene : scenesOf(maps)) {
    svg::Plot errors;
    errors.title = scene + ": error against real time";
    errors.x = {"lightmap resolution N (N \u00d7 N texels)", svg::Scale::Log2, false};
    errors.y = {"error against real time", svg::Scale::Log10, false};  // the legend names the lines
    svg::Plot times;
    times.title = scene + ": bake and frame time";
    times.x = errors.x;
    times.y = {"median time, ms", svg::Scale::Log10, false};
    std::map<std::string, std::size_t> errorLines, timeLines;
    Entries rows;
    for (const BenchEntry* e : maps) {
      if (e->name.scene != scene) continue;
      rows.push_back(e);
      const double n = *lightmapResolution(*e);
      const std::string group = byBackend ? backendOf(*e) : "";
      const std::size_t colourBase = byBackend ? m.backendIndex(group) : 0;
      const auto add = [&](svg::Plot& plot, std::map<std::string, std::size_t>& lines, const std::string& what,
                           std::size_t colour, bool dashed, std::optional<double> y) {
        if (!y) return;
        svg::Point p = plainPoint(n, *y);
        p.id = backendOf(*e) + "/" + e->name.mode + " " + what;
        lineOf(plot, lines, byBackend ? group + " " + what : what, colour, dashed).points.push_back(p);
      };
      add(errors, errorLines, "err_rmse", colourBase, false, counter(*e, "err_rmse"));
      add(errors, errorLines, "err_max_abs", byBackend ? colourBase : 1, true, counter(*e, "err_max_abs"));
      add(times, timeLines, "bake", colourBase, false, counter(*e, "bake_ms"));
      add(times, timeLines, "frame", byBackend ? colourBase : 1, true, e->medianMs);
    }
    for (svg::Plot* plot : {&errors, &times})
      for (svg::Series& line : plot->series)
        std::stable_sort(line.points.begin(), line.points.end(),
                         [](const svg::Point& a, const svg::Point& b) { return a.x < b.x; });
    out << "<h3>" << escapeText(scene) << "</h3>\n<div class=\"plotbox\">" << svg::render(errors)
        << svg::render(times) << "</div>\n";
    for (const BenchEntry* e : candidates)  // the real-time point of the same scene
      if (e->name.kind == "frame" && e->name.scene == scene && e->name.mode == "realtime") rows.push_back(e);
    out << "<table class=\"bench lightmap\">\n<tr><th>backend</th><th>mode</th><th>N</th><th>bake ms</th>"
           "<th>bake runs</th><th>median frame ms</th><th>err_rmse</th><th>err_max_abs</th><th>err_psnr_db</th>"
           "<th>err_perceptual_fail</th></tr>\n";
    for (const BenchEntry* e : rows) {
      out << "<tr><td>" << escapeText(backendOf(*e)) << "</td><td>" << escapeText(e->name.mode) << "</td>";
      if (!e->error.empty() && !e->medianMs) {
        out << "<td class=\"err\" colspan=\"8\">error: " << escapeText(e->error) << "</td></tr>\n";
        continue;
      }
      out << "<td class=\"n\">" << fmt(lightmapResolution(*e)) << "</td><td class=\"n\">"
          << fmt(counter(*e, "bake_ms")) << "</td><td class=\"n\">" << fmt(counter(*e, "bake_runs"))
          << "</td><td class=\"n\">" << fmt(e->medianMs) << "</td><td class=\"n\">"
          << fmt(counter(*e, "err_rmse")) << "</td><td class=\"n\">" << fmt(counter(*e, "err_max_abs"))
          << "</td><td class=\"n\">" << fmt(counter(*e, "err_psnr_db")) << "</td><td class=\"n\">"
          << fmt(counter(*e, "err_perceptual_fail")) << "</td></tr>\n";
    }
    out << "</table>\n";
  }
}

// Adds `e` (median, min-max whiskers, at its curve x) to the line of `group`,
// starting that line in colour `colourIndex` the first time.
void addCurvePoint(svg::Plot& plot, std::map<std::string, std::size_t>& seriesOf, const std::string& group,
                   std::size_t colourIndex, const BenchEntry& e) {
  auto [it, added] = seriesOf.emplace(group, plot.series.size());
  if (added) {
    svg::Series s;
    s.name = group;
    s.colour = svg::colour(colourIndex);
    plot.series.push_back(s);
  }
  svg::Point p;
  p.x = *curveX(e.name.x);
  p.y = *e.medianMs;
  p.yLow = e.minMs;
  p.yHigh = e.maxMs;
  p.id = e.name.full;
  plot.series[it->second].points.push_back(p);
}

// One line per group (backend or mode) of frame time against the curve's x.
std::string curvePlot(const Model& m, const std::string& title, const std::string& scene, const Entries& entries,
                      bool byBackend) {
  svg::Plot plot;
  plot.title = title;
  plot.x = {xAxisLabel(scene), scene == "curve-lights" ? svg::Scale::Log2 : svg::Scale::Log10, false};
  double lo = INFINITY, hi = 0;
  for (const BenchEntry* e : entries) lo = std::min(lo, *e->medianMs), hi = std::max(hi, *e->medianMs);
  plot.y = {"median frame time, ms", lo > 0 && hi / lo > 20 ? svg::Scale::Log10 : svg::Scale::Linear, true};
  std::map<std::string, std::size_t> seriesOf;
  for (const BenchEntry* e : entries) {
    const std::string group = byBackend ? backendOf(*e) : e->name.mode;
    addCurvePoint(plot, seriesOf, group, byBackend ? m.backendIndex(group) : m.modeIndex(group), *e);
  }
  for (svg::Series& s : plot.series)
    std::stable_sort(s.points.begin(), s.points.end(), [](const svg::Point& a, const svg::Point& b) { return a.x < b.x; });
  return svg::render(plot);
}

void costCurveSection(std::ostringstream& out, const Model& m, const Entries& candidates, bool byBackend) {
  Entries curves;
  for (const BenchEntry* e : candidates)
    if (e->name.kind == "frame" && isCurve(*e)) curves.push_back(e);
  out << "<h2 id=\"curves\">Cost curves</h2>\n<p class=\"note\">Median frame time (<code>frame</code>: draw, no "
         "readback) against the load; the whiskers span the minimum and maximum over the repetitions.</p>\n";
  if (curves.empty()) {
    out << "<p>No cost-curve benchmarks.</p>\n";
    return;
  }
  for (const std::string& scene : scenesOf(curves)) {
    Entries ofScene;
    for (const BenchEntry* e : curves)
      if (e->name.scene == scene) ofScene.push_back(e);
    if (byBackend) {  // one plot per mode, one line per backend
      std::vector<std::string> modes;
      for (const BenchEntry* e : ofScene)
        if (std::find(modes.begin(), modes.end(), e->name.mode) == modes.end()) modes.push_back(e->name.mode);
      for (const std::string& mode : modes) {
        Entries ofMode;
        for (const BenchEntry* e : ofScene)
          if (e->name.mode == mode) ofMode.push_back(e);
        out << curvePlot(m, scene + ", " + mode, scene, ofMode, true);
      }
    } else {
      out << curvePlot(m, scene, scene, ofScene, false);
    }
  }
}

std::string fitText(const ComplexityFit& fit) {
  std::string text = fit.family.mode + ": ";
  if (fit.coefficientMs) text += fmt(*fit.coefficientMs, 3) + " ms \u00b7 ";
  text += fit.bigO.empty() ? "?" : fit.bigO == "(1)" ? "1" : fit.bigO;
  if (fit.rms) text += ", RMS " + fmt(*fit.rms * 100, 3) + " %";
  return text;
}

void prepareSection(std::ostringstream& out, const Model& m) {
  const Entries prepare = m.select(isPrepare);
  out << "<h2 id=\"prepare\">CPU preparation</h2>\n<p class=\"note\">Selection (SPEC 5) and packing on the CPU, "
         "log-log. Dashed: Google Benchmark's complexity fit (coefficient \u00b7 f(N), and its normalised RMS "
         "error).</p>\n";
  if (prepare.empty()) {
    out << "<p>No CPU preparation benchmarks.</p>\n";
    return;
  }
  Entries curves;
  for (const BenchEntry* e : prepare)
    if (isCurve(*e)) curves.push_back(e);
  for (const std::string& scene : scenesOf(curves)) {
    svg::Plot plot;
    plot.title = "prepare, " + scene;
    plot.x = {xAxisLabel(scene), svg::Scale::Log10, false};
    plot.y = {"median time, ms", svg::Scale::Log10, false};
    std::vector<const ComplexityFit*> fits;
    std::map<std::string, std::size_t> seriesOf;
    for (const BenchEntry* e : curves) {
      if (e->name.scene != scene) continue;
      addCurvePoint(plot, seriesOf, e->name.mode, m.modeIndex(e->name.mode), *e);
    }
    const std::size_t measured = plot.series.size();
    for (std::size_t i = 0; i < measured; ++i) {
      svg::Series& s = plot.series[i];
      std::stable_sort(s.points.begin(), s.points.end(), [](const auto& a, const auto& b) { return a.x < b.x; });
      for (const ComplexityFit& fit : m.set.fits) {
        if (fit.family.kind != "prepare" || fit.family.scene != scene || fit.family.mode != s.name) continue;
        fits.push_back(&fit);
        svg::Series line;
        line.name = s.name + " fit " + (fit.bigO.empty() ? "?" : fit.bigO);
        line.colour = s.colour;
        line.dashed = true;
        line.markers = false;
        line.cssClass = "fit";
        const double x0 = s.points.front().x, x1 = s.points.back().x;
        for (int k = 0; k <= 40 && x1 > x0; ++k) {
          const double x = x0 * std::pow(x1 / x0, k / 40.0);
          if (const auto y = fit.at(x); y && *y > 0) line.points.push_back(plainPoint(x, *y));
        }
        if (line.points.size() >= 2) plot.series.push_back(line);
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
  // Fits of families that are not plotted.
  for (const ComplexityFit& fit : m.set.fits)
    if (fit.family.kind != "prepare")
      out << "<p class=\"fits\">" << escapeText(fit.family.full) << ": " << escapeText(fitText(fit)) << "</p>\n";
  out << "<h3>prepare (" << prepare.size() << ")</h3>\n";
  benchTable(out, prepare);
}

}  // namespace

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

std::string benchPageFile(const std::string& backend) {
  std::string name;
  for (const char c : backend) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' ||
                    c == '_' || c == '-';
    name += ok ? c : '_';
  }
  if (name.empty() || name == "index" || name[0] == '.') name = "backend-" + name;
  return name + ".html";
}

std::vector<std::string> benchBackends(const Json& bench) {
  std::vector<std::string> out;
  const auto add = [&](const std::string& name) {
    if (!name.empty() && std::find(out.begin(), out.end(), name) == out.end()) out.push_back(name);
  };
  for (const Json& b : arrayField(bench, "backends")) add(textField(b, "backend"));
  for (const BenchEntry& e : readBenchFile(bench).entries)
    if (!isPrepare(e) && e.section.empty() && !e.name.backend.empty() && e.name.backend != "cpu")
      add(e.name.backend);
  return out;
}

std::string benchOverviewHtml(const Json& bench) {
  const Model m(bench);
  std::ostringstream out;
  pageStart(out, m, "lightcts benchmarks", "");
  runMeta(out, m);

  out << "<h2 id=\"backends\">Backends</h2>\n<table class=\"bench\">\n<tr><th>backend</th><th>status</th>"
         "<th>device</th><th>driver</th><th>driver version</th><th>API version</th><th>benchmarks</th>"
         "<th>message</th></tr>\n";
  for (const std::string& b : m.backends) {
    const Json& j = backendJson(bench, b);
    const Json& device = objectField(j, "device");
    const auto count = m.select([&](const BenchEntry& e) { return !isPrepare(e) && backendOf(e) == b; }).size();
    out << "<tr><td><a href=\"" << escapeText(percentEncodePath(benchPageFile(b))) << "\">" << escapeText(b)
        << "</a></td><td>" << escapeText(textField(j, "status")) << "</td><td>"
        << escapeText(textField(device, "name")) << "</td><td>" << escapeText(textField(device, "driver"))
        << "</td><td>" << escapeText(textField(device, "driver_version")) << "</td><td>"
        << escapeText(textField(device, "api_version")) << "</td><td class=\"n\">" << count << "</td><td>"
        << escapeText(textField(j, "message")) << "</td></tr>\n";
  }
  out << "</table>\n<p class=\"note\">Each backend's page has the table of every one of its benchmarks "
         "(median, spread, counters).</p>\n";

  const Entries gpu = m.select([](const BenchEntry& e) { return !isPrepare(e); });
  speedErrorSection(out, m, gpu, true);
  lightmapSection(out, m, gpu, true);
  costCurveSection(out, m, gpu, true);
  prepareSection(out, m);
  out << "</body>\n</html>\n";
  return out.str();
}

std::string benchBackendHtml(const Json& bench, const std::string& backend) {
  const Model m(bench);
  std::ostringstream out;
  pageStart(out, m, "lightcts benchmarks: " + backend, backend);
  runMeta(out, m);

  const Json& j = backendJson(bench, backend);
  const Json& device = objectField(j, "device");
  out << "<h2 id=\"device\">Device</h2>\n<dl class=\"meta\">\n";
  metaRow(out, "status", textField(j, "status"));
  metaRow(out, "message", textField(j, "message"));
  metaRow(out, "device", textField(device, "name"));
  metaRow(out, "driver", textField(device, "driver"));
  metaRow(out, "driver version", textField(device, "driver_version"));
  metaRow(out, "API version", textField(device, "api_version"));
  const Json& context = objectField(j, "context");
  for (auto it = context.begin(); it != context.end(); ++it)
    if (it->is_primitive()) metaRow(out, "context." + it.key(), textField(context, it.key()));
  out << "</dl>\n";

  const Entries mine = m.select([&](const BenchEntry& e) { return !isPrepare(e) && backendOf(e) == backend; });
  speedErrorSection(out, m, mine, false);
  lightmapSection(out, m, mine, false);
  costCurveSection(out, m, mine, false);
  out << "<h2 id=\"table\">Every benchmark</h2>\n<p class=\"note\">Times in ms: the median over the repetitions "
         "(Google Benchmark's median aggregate when present), their minimum, maximum and standard deviation, and "
         "their count; counters are medians too. <code>\u00d7 limit</code> is the median over "
         "<code>limit_ms</code>, the physical limit at the calibrated peak rate.</p>\n";
  if (mine.empty()) out << "<p>No benchmarks.</p>\n";
  tablesByKind(out, mine);
  out << "</body>\n</html>\n";
  return out.str();
}

void writeBenchReport(const Json& bench, const fs::path& outDir) {
  if (!bench.is_object()) throw std::invalid_argument("bench.json: not a JSON object");
  if (const auto f = bench.find("format"); f != bench.end() && *f != "lightcts-bench")
    throw std::invalid_argument("bench.json: format is " + f->dump() + ", not \"lightcts-bench\"");
  imaging::writeFileAtomically(outDir / "index.html", benchOverviewHtml(bench));
  for (const std::string& backend : benchBackends(bench))
    imaging::writeFileAtomically(outDir / benchPageFile(backend), benchBackendHtml(bench, backend));
}

}  // namespace reports
