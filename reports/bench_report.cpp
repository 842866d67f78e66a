// The benchmark pages: the overview (every backend) and one page per backend,
// put together from the sections of bench_sections.h in the shared page
// frame (html_page.h), with the run's metadata and the backends' devices.
#include "reports/bench_report.h"

#include "imaging/atomic_file.h"
#include "reports/bench_page_model.h"
#include "reports/bench_sections.h"
#include "reports/bench_table.h"
#include "reports/html_escape.h"
#include "reports/html_page.h"
#include "reports/html_sections.h"
#include "reports/json_fields.h"
#include "reports/result_fields.h"
#include "results/run_records.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace reports {
namespace {

namespace fs = std::filesystem;
using namespace benchpages;

// The benchmark pages' own rules; the base stylesheet is html_page's.
constexpr const char* kBenchStyle = R"(nav a { margin-right: 1em; }
table.bench { font-size: .85em; }
svg.plot { max-width: 100%; height: auto; border: 1px solid #ddd; display: block; margin: .5em 0; }
.plotbox { display: flex; flex-wrap: wrap; align-items: flex-start; gap: 1em; }
.fits { font-size: .9em; }
tr.front td:first-child, tr.front td:nth-child(2) { font-weight: bold; }
tr.broken td { background: #fee; }
.err { color: #b00; } .note { color: #555; font-size: .9em; }
.warn { background: #fff3cd; border: 1px solid #e0a800; padding: .5em; }
)";

std::string pageLink(const std::string& backend) {
  return "<a href=\"" + escapeText(percentEncodePath(benchPageFile(backend))) + "\">" + escapeText(backend) + "</a>";
}

// The page frame, the title and the navigation between the pages (`current`
// empty: the overview).
void pageStart(std::ostream& out, const BenchModel& m, const std::string& title, const std::string& current) {
  html::pageStart(out, title, kBenchStyle);
  out << "<h1>" << escapeText(title) << "</h1>\n<nav>";
  out << (current.empty() ? "<strong>overview</strong>" : "<a href=\"index.html\">overview</a>") << ' ';
  for (const std::string& b : m.backends)
    out << (b == current ? "<strong>" + escapeText(b) + "</strong>" : pageLink(b)) << ' ';
  out << "</nav>\n";
}

void metaRow(std::ostream& out, const std::string& key, const std::string& value) {
  if (value.empty()) return;
  out << "<dt>" << escapeText(key) << "</dt><dd>" << escapeText(value) << "</dd>\n";
}

// The warning of a run whose machine changed under it: the two
// calibrations differ by more than kPeakDriftLimit, so its times and limits
// are not comparable with a quiet run's. Computed from the two rates, not
// read from peak_drift, so a hand-edited or older file cannot hide it.
void peakDriftWarning(std::ostream& out, const Json& bench) {
  const std::optional<PeakDrift> drift = peakDriftOf(bench);
  if (!drift || !drift->flagged) return;
  out << "<p class=\"warn\" id=\"peak-drift\"><strong>Loaded machine:</strong> the peak-rate calibration before "
         "the timed runs and the one after them differ by "
      << fmt(100 * drift->difference, 3) << "% (more than " << fmt(100 * kPeakDriftLimit, 3)
      << "%, as |after &minus; before| / the smaller). Something else ran during this benchmark; its times and "
         "physical limits are not comparable with a quiet run's.</p>\n";
}

void runMeta(std::ostream& out, const BenchModel& m) {
  const Json& b = m.bench;
  const results::MachineRecord machine = results::MachineRecord::fromJson(objectField(b, "machine"));
  const Json& peak = objectField(b, "peak");
  out << "<h2 id=\"run\">Run</h2>\n<dl class=\"meta\">\n";
  metaRow(out, "revision", textField(b, "lightcts_revision"));
  metaRow(out, "started (UTC)", textField(b, "started_utc"));
  if (const auto d = numberField(b, "duration_s")) metaRow(out, "duration", formatSeconds(*d) + " s");
  metaRow(out, "command", textField(b, "command"));
  metaRow(out, "machine", machine.hostname);
  metaRow(out, "cpu", machine.cpu);
  metaRow(out, "cores", std::to_string(machine.cores));
  metaRow(out, "os", machine.os);
  if (const auto g = numberField(peak, "gflops")) {
    std::string text = fmt(*g) + " GFLOP/s";
    if (const auto c = textField(peak, "cores"); !c.empty()) text += " on " + c + " cores";
    if (const auto n = textField(peak, "median_of"); !n.empty()) text += ", median of " + n;
    if (const auto k = textField(peak, "kernel"); !k.empty()) text += " (" + k + ")";
    metaRow(out, "peak rate", text);
  }
  if (const auto g = numberField(objectField(b, "peak_after"), "gflops"))
    metaRow(out, "peak rate after", fmt(*g) + " GFLOP/s (calibrated again after the timed runs)");
  out << "</dl>\n";
  peakDriftWarning(out, b);
}

const Json& backendJson(const Json& bench, const std::string& backend) {
  static const Json none = Json::object();
  for (const Json& b : arrayField(bench, "backends"))
    if (textField(b, "backend") == backend) return b;
  return none;
}

// The overview's table of backends: one row per backend, linked to its page.
void backendsTable(std::ostream& out, const BenchModel& m) {
  const auto device = [&m](const char* key) {
    return [&m, key](const std::string& b) {
      return html::cell(textField(objectField(backendJson(m.bench, b), "device"), key));
    };
  };
  const auto field = [&m](const char* key) {
    return [&m, key](const std::string& b) { return html::cell(textField(backendJson(m.bench, b), key)); };
  };
  Table<std::string> table;
  table.cssClass = "bench";
  table.columns = {
      {"backend", [](const std::string& b) { return "<td>" + pageLink(b) + "</td>"; }},
      {"status", field("status")},
      {"device", device("name")},
      {"driver", device("driver")},
      {"driver version", device("driver_version")},
      {"API version", device("api_version")},
      {"benchmarks",
       [&m](const std::string& b) {
         return valueCell(double(m.select([&](const BenchEntry& e) { return !isPrepare(e) && backendOf(e) == b; })
                                     .size()));
       }},
      {"message", field("message")},
  };
  writeTable(out, table, m.backends);
}

}  // namespace

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
  const BenchModel m(bench);
  std::ostringstream out;
  pageStart(out, m, "lightcts benchmarks", "");
  runMeta(out, m);
  out << "<h2 id=\"backends\">Backends</h2>\n";
  backendsTable(out, m);
  out << "<p class=\"note\">Each backend's page has the table of every one of its benchmarks "
         "(median, spread, counters).</p>\n";

  const Entries gpu = m.select([](const BenchEntry& e) { return !isPrepare(e); });
  speedErrorSection(out, m, gpu, true);
  shadowMapSection(out, m, gpu);
  lightmapSection(out, m, gpu, true);
  costCurveSection(out, m, gpu, true);
  twoTermSection(out, m, gpu);
  prepareSection(out, m);
  html::pageEnd(out);
  return out.str();
}

std::string benchBackendHtml(const Json& bench, const std::string& backend) {
  const BenchModel m(bench);
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
  shadowMapSection(out, m, mine);
  lightmapSection(out, m, mine, false);
  costCurveSection(out, m, mine, false);
  twoTermSection(out, m, mine);
  out << "<h2 id=\"table\">Every benchmark</h2>\n<p class=\"note\">Times in ms: the median over the repetitions "
         "(Google Benchmark's median aggregate when present), their minimum, maximum and standard deviation, and "
         "their count; counters are medians too. <code>\u00d7 limit</code> is the median over "
         "<code>limit_ms</code>, the physical limit at the calibrated peak rate.</p>\n";
  if (mine.empty()) out << "<p>No benchmarks.</p>\n";
  tablesByKind(out, mine);
  html::pageEnd(out);
  return out.str();
}

std::optional<PeakDrift> peakDrift(std::optional<double> beforeGflops, std::optional<double> afterGflops) {
  if (!beforeGflops || !afterGflops || !(*beforeGflops > 0) || !(*afterGflops > 0)) return std::nullopt;
  PeakDrift drift;
  drift.difference = std::abs(*afterGflops - *beforeGflops) / std::min(*beforeGflops, *afterGflops);
  drift.flagged = drift.difference > kPeakDriftLimit;
  return drift;
}

std::optional<PeakDrift> peakDriftOf(const Json& bench) {
  if (!bench.is_object()) return std::nullopt;
  return peakDrift(numberField(objectField(bench, "peak"), "gflops"),
                   numberField(objectField(bench, "peak_after"), "gflops"));
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
