// The `lightmap-N` modes (docs/bench-format.md) against N: the error of the
// baked image against the same lights in real time, and the bake time beside
// the frame time; one line per backend (overview) or per quantity (a backend
// page), then the table with the scene's `realtime` point for comparison.
#include "reports/bench_sections.h"
#include "reports/bench_table.h"
#include "reports/html_escape.h"
#include "reports/svg_plot.h"
#include "results/bench_names.h"

namespace reports::benchpages {

namespace bench = results::bench;
namespace {

// The two plots of one lightmap scene, filled a point at a time.
struct LightmapPlots {
  svg::Plot errors, times;

  explicit LightmapPlots(const std::string& scene) {
    errors.title = scene + ": error against real time";
    errors.x = {"lightmap resolution N (N \u00d7 N texels)", svg::Scale::Log2, false};
    errors.y = {"error against real time", svg::Scale::Log10, false};  // the legend names the lines
    times.title = scene + ": bake and frame time";
    times.x = errors.x;
    times.y = {"median time, ms", svg::Scale::Log10, false};
  }
};

// e's four quantities at its N: err_rmse and err_max_abs, bake and frame time.
// A backend's page colours the quantities; the overview colours the backends
// and dashes the second quantity of each plot.
void addPoints(svg::SeriesBuilder& errors, svg::SeriesBuilder& times, const BenchModel& m, const BenchEntry& e,
               bool byBackend) {
  const double n = *lightmapResolution(e);
  const std::string group = byBackend ? backendOf(e) : "";
  const std::size_t colourBase = byBackend ? m.backendIndex(group) : 0;
  const auto add = [&](svg::SeriesBuilder& plot, const std::string& what, bool second, std::optional<double> y) {
    if (!y) return;
    svg::Point p = svg::pointAt(n, *y);
    p.id = backendOf(e) + "/" + e.name.mode + " " + what;
    const std::size_t colour = second && !byBackend ? 1 : colourBase;
    plot.add(byBackend ? group + " " + what : what, {colour, true, second}, p);
  };
  if (!isBroken(e)) {  // a broken image has no error to plot
    add(errors, "err_rmse", false, counter(e, bench::kErrRmse));
    add(errors, "err_max_abs", true, counter(e, bench::kErrMaxAbs));
  }
  add(times, "bake", false, counter(e, bench::kBakeMs));
  add(times, "frame", true, e.medianMs);
}

Table<const BenchEntry*> lightmapTable() {
  Table<const BenchEntry*> table;
  table.cssClass = "bench lightmap";
  table.columns = {
      textColumn("backend", backendOf),
      markedTextColumn("mode", [](const BenchEntry& e) { return e.name.mode; }),
      numberColumn("N", lightmapResolution),
      counterColumn("bake ms", bench::kBakeMs),
      counterColumn("bake runs", bench::kBakeRuns),
      numberColumn("median frame ms", [](const BenchEntry& e) { return e.medianMs; }),
      cpuColumn(),
      cvColumn(),
      counterColumn("err_rmse", bench::kErrRmse),
      counterColumn("err_max_abs", bench::kErrMaxAbs),
      counterColumn("err_psnr_db", bench::kErrPsnrDb),
      counterColumn("err_perceptual_fail", bench::kErrPerceptualFail),
  };
  table.failure = [](const BenchEntry* e) { return failureOf(*e); };
  table.keyColumns = 2;
  return table;
}

}  // namespace

void lightmapSection(std::ostream& out, const BenchModel& m, const Entries& candidates, bool byBackend) {
  const Entries maps = filter(candidates, [](const BenchEntry& e) {
    return e.name.kind == bench::kFrame && e.medianMs && lightmapResolution(e);
  });
  if (maps.empty()) return;
  out << "<h2 id=\"lightmap\">Lightmap resolution</h2>\n<p class=\"note\">The <code>lightmap-N</code> modes: the "
         "scene's lights baked into an N \u00d7 N lightmap (SPEC 3.6), drawn and compared with the "
         "<code>--ideal</code> reference of the same lights lit in real time, so the error is what the bake loses "
         "(resolution, bilinear filtering, and the baked shadow that real time does not draw). The bake time is the "
         "median of fresh bakes (no cache, every core) of that process; the frame time is the median draw "
         "(<code>frame</code>). The <code>realtime</code> row is the same lights lit per pixel, against the same "
         "reference.</p>\n";
  for (const std::string& scene : scenesOf(maps)) {
    LightmapPlots plots(scene);
    svg::SeriesBuilder errors(plots.errors), times(plots.times);
    Entries rows = ofScene(maps, scene);
    for (const BenchEntry* e : rows) addPoints(errors, times, m, *e, byBackend);
    svg::sortPointsByX(plots.errors);
    svg::sortPointsByX(plots.times);
    out << "<h3>" << escapeText(scene) << "</h3>\n<div class=\"plotbox\">" << svg::render(plots.errors)
        << svg::render(plots.times) << "</div>\n";
    for (const BenchEntry* e : candidates)  // the real-time point of the same scene
      if (e->name.kind == bench::kFrame && e->name.scene == scene && e->name.mode == "realtime") rows.push_back(e);
    writeTable(out, lightmapTable(), rows);
  }
}

}  // namespace reports::benchpages
