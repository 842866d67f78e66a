#include "reports/bench_table.h"

#include "reports/html_escape.h"
#include "reports/html_sections.h"
#include "results/bench_names.h"

#include <algorithm>
#include <set>
#include <utility>

namespace reports::benchpages {

namespace bench = results::bench;

std::string valueCell(const std::optional<double>& value, int digits) { return html::numberCell(fmt(value, digits)); }

EntryColumn textColumn(std::string header, std::function<std::string(const BenchEntry&)> text) {
  return {std::move(header), [text = std::move(text)](const BenchEntry* e) { return html::cell(text(*e)); }};
}

EntryColumn numberColumn(std::string header, EntryValue value, int digits) {
  return {std::move(header), [value = std::move(value), digits](const BenchEntry* e) {
            return valueCell(value(*e), digits);
          }};
}

EntryColumn counterColumn(std::string header, std::string_view key) {
  return numberColumn(std::move(header), [key](const BenchEntry& e) { return counter(e, key); });
}

std::string brokenMark(const BenchEntry& e) {
  std::string mark;
  if (isBroken(e)) mark += " <span class=\"err\">broken: " + fmt(counter(e, bench::kErrNonfinitePixels)) + " non-finite pixels</span>";
  // A device time its wall time rules out (suite/bench/time_source.h): the
  // entry is wall-timed, and says why.
  if (counter(e, bench::kDeviceTimeFlagged))
    mark += " <span class=\"err\">" + escapeText(e.label.empty() ? "wall time: a device time was flagged" : e.label) + "</span>";
  return mark;
}

EntryColumn markedTextColumn(std::string header, std::function<std::string(const BenchEntry&)> text) {
  return {std::move(header), [text = std::move(text)](const BenchEntry* e) {
            return "<td>" + escapeText(text(*e)) + brokenMark(*e) + "</td>";
          }};
}

EntryColumn cpuColumn() {
  return numberColumn("CPU ms", [](const BenchEntry& e) { return e.cpuMedianMs; });
}

EntryColumn cvColumn() {
  return numberColumn(
      "CV %", [](const BenchEntry& e) { return e.cv ? std::optional(*e.cv * 100) : std::nullopt; }, 3);
}

std::optional<std::string> failureOf(const BenchEntry& e) {
  if (!e.error.empty() && !e.medianMs) return e.error;
  return std::nullopt;
}

std::string tableHead(std::string_view cssClass, const std::vector<std::string>& headers) {
  std::string head = "<table class=\"" + escapeText(cssClass) + "\">\n<tr>";
  for (const std::string& h : headers) head += "<th>" + escapeText(h) + "</th>";
  return head + "</tr>\n";
}

std::string failureCells(std::size_t span, const std::string& message) {
  return "<td class=\"err\" colspan=\"" + std::to_string(span) + "\">error: " + escapeText(message) + "</td>";
}

namespace {

// A column of numbers of an entry; shown only when some row has a value.
struct NumberColumn {
  std::string header;
  std::function<std::optional<double>(const BenchEntry&)> value;
  int digits = 4;
  bool withTimes = false;  // shown whenever the median is ("-" in rows without a value)
};

std::vector<NumberColumn> numberColumns(const Entries& entries) {
  std::vector<NumberColumn> columns = {
      {"median ms", [](const BenchEntry& e) { return e.medianMs; }},
      {"CPU ms", [](const BenchEntry& e) { return e.cpuMedianMs; }, 4, true},
      {"min ms", [](const BenchEntry& e) { return e.minMs; }},
      {"max ms", [](const BenchEntry& e) { return e.maxMs; }},
      {"stddev ms", [](const BenchEntry& e) { return e.stddevMs; }, 3},
      {"CV %", [](const BenchEntry& e) { return e.cv ? std::optional(*e.cv * 100) : std::nullopt; }, 3, true},
      {"n", [](const BenchEntry& e) { return e.count ? std::optional<double>(e.count) : std::nullopt; }},
  };
  const std::vector<std::pair<std::string_view, std::string>> known = {
      {bench::kWallMs, "wall ms"}, {bench::kDeviceMs, "device ms"}, {bench::kPixels, "pixels"}, {bench::kTriangles, "triangles"}, {bench::kLights, "lights"},
      {bench::kLightsPerPixel, "lights/pixel"}, {bench::kPixelsPerS, "pixels/s"},
      {bench::kPixelLightEvalsPerS, "pixel-light evals/s"}, {bench::kErrRmse, "err_rmse"},
      {bench::kErrMaxAbs, "err_max_abs"}, {bench::kErrPsnrDb, "err_psnr_db"},
      {bench::kErrPerceptualFail, "err_perceptual_fail"}, {bench::kErrNonfinitePixels, "err_nonfinite_pixels"},
      {bench::kBakeMs, "bake ms"}, {bench::kBakeRuns, "bake runs"},
      {bench::kLightmapTexels, "lightmap texels"}, {bench::kFlopsPerPixelLight, "flops/pixel-light"},
      {bench::kLimitMs, "limit ms"}, {bench::kDeviceTimeFlagged, "device time flagged"}};
  for (const auto& [key, header] : known)
    columns.push_back({header, [key = key](const BenchEntry& e) { return counter(e, key); }});
  columns.push_back({"\u00d7 limit", limitRatio, 3});
  std::set<std::string> seen;
  for (const auto& [key, header] : known) seen.insert(std::string(key));
  for (const BenchEntry* e : entries)
    for (const auto& [key, value] : e->counters)
      if (seen.insert(key).second)
        columns.push_back({key, [key = key](const BenchEntry& x) { return counter(x, key); }});
  const bool timed =
      std::any_of(entries.begin(), entries.end(), [](const BenchEntry* e) { return e->medianMs.has_value(); });
  std::vector<NumberColumn> used;
  for (NumberColumn& c : columns)
    if ((c.withTimes && timed) ||
        std::any_of(entries.begin(), entries.end(), [&](const BenchEntry* e) { return c.value(*e).has_value(); }))
      used.push_back(std::move(c));
  return used;
}

}  // namespace

void benchTable(std::ostream& out, const Entries& entries) {
  if (entries.empty()) return;
  Table<const BenchEntry*> table;
  table.cssClass = "bench";
  table.columns.push_back(markedTextColumn("benchmark", [](const BenchEntry& e) { return e.name.full; }));
  table.rowClass = [](const BenchEntry* e) { return std::string(isBroken(*e) ? "broken" : ""); };
  for (NumberColumn& c : numberColumns(entries)) table.columns.push_back(numberColumn(c.header, c.value, c.digits));
  table.failure = [](const BenchEntry* e) { return failureOf(*e); };
  writeTable(out, table, entries);
}

void tablesByKind(std::ostream& out, const Entries& entries) {
  std::vector<std::string> kinds;
  for (const BenchEntry* e : entries)
    if (std::find(kinds.begin(), kinds.end(), e->name.kind) == kinds.end()) kinds.push_back(e->name.kind);
  for (const std::string& kind : kinds) {
    const Entries ofKind = filter(entries, [&](const BenchEntry& e) { return e.name.kind == kind; });
    out << "<h3>" << escapeText(kind) << " (" << ofKind.size() << ")</h3>\n";
    benchTable(out, ofKind);
  }
}

}  // namespace reports::benchpages
