#include "reports/run_compare.h"

#include "imaging/atomic_file.h"
#include "reports/html_escape.h"
#include "reports/html_page.h"

#include <cmath>
#include <cstdio>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <unordered_map>
#include <unordered_set>

namespace reports {
namespace {

struct TestView {
  std::string verdict;  // as the run says it
  bool runFailure = false;  // an unknown word included (it reads as a Crash)
  std::optional<double> tightness;  // finite and not negative, else nullopt
};

// The named tests of a run, in file order, first entry of a name only.
struct TestIndex {
  std::vector<std::string> order;
  std::unordered_map<std::string, TestView> byName;
};

TestIndex indexTests(const results::RunRecord& run) {
  TestIndex index;
  for (const results::TestRecord& test : run.tests) {
    if (test.name.empty() || index.byName.contains(test.name)) continue;
    TestView view{test.verdictWord(), comparison::isRunFailure(test.verdict), std::nullopt};
    if (test.metrics && !test.metrics->tightnessIsInfinite && test.metrics->tightness &&
        std::isfinite(*test.metrics->tightness) && *test.metrics->tightness >= 0)
      view.tightness = *test.metrics->tightness;
    index.order.push_back(test.name);
    index.byName.emplace(test.name, std::move(view));
  }
  return index;
}

bool beyondTwice(double oldValue, double newValue) {
  if (oldValue == newValue) return false;  // 0 and 0 included
  if (oldValue == 0 || newValue == 0) return true;
  const double ratio = newValue / oldValue;
  return ratio > 2.0 || ratio < 0.5;
}

std::string ratioText(double oldValue, double newValue) {
  if (oldValue == 0) return "from 0";
  std::string text = "x";  // not "x" + ...: GCC 12 warns falsely (-Wrestrict) on that
  text += formatNumber(newValue / oldValue);
  return text;
}

std::string shownVerdict(std::string_view verdict) { return verdict.empty() ? "(none)" : std::string(verdict); }

std::string plural(std::size_t n, std::string_view one, std::string_view many) {
  return std::to_string(n) + " " + std::string(n == 1 ? one : many);
}

std::string summaryLine(const RunComparison& c) {
  return plural(c.regressions.size(), "regression", "regressions") + ", " + plural(c.fixes.size(), "fix", "fixes") +
         ", " + plural(c.changes.size(), "other change", "other changes") + ", " + std::to_string(c.added.size()) +
         " new, " + std::to_string(c.removed.size()) + " removed, " +
         plural(c.tightness.size(), "tightness change", "tightness changes") + " beyond 2x";
}

// CSS class of a verdict cell: the colours of piglit's summary.
std::string_view verdictClass(std::string_view verdict) {
  const auto known = comparison::parseVerdict(verdict);
  if (!known) return "unknown";
  switch (*known) {
    case comparison::Verdict::Pass: return "pass";
    case comparison::Verdict::Fail:
    case comparison::Verdict::UnexpectedPass: return "fail";
    case comparison::Verdict::Crash:
    case comparison::Verdict::Timeout:
    case comparison::Verdict::NotRun: return "crash";
    case comparison::Verdict::QualityWarning:
    case comparison::Verdict::Flake: return "warn";
    case comparison::Verdict::NotSupported:
    case comparison::Verdict::ExpectedFail: return "skip";
  }
  return "unknown";
}

std::string verdictCell(std::string_view verdict) {
  return "<td class=\"v " + std::string(verdictClass(verdict)) + "\">" + escapeText(shownVerdict(verdict)) + "</td>";
}

constexpr std::string_view kPageStyle =
    "td.v { font-weight: bold; text-align: center; }\n"
    "td.pass { background: #b6e3a8; } td.fail { background: #f4a6a6; } td.crash { background: #c86464; color: #fff; }\n"
    "td.warn { background: #f6d98b; } td.skip { background: #ddd; } td.unknown { background: #e0a0e0; }\n"
    "tr.regression th { color: #a00; } p.none { color: #666; }\n";

void changeTable(std::ostream& html, std::string_view id, std::string_view title,
                 const std::vector<VerdictChange>& rows) {
  html << "<h2 id=\"" << id << "\">" << escapeText(title) << " (" << rows.size() << ")</h2>\n";
  if (rows.empty()) {
    html << "<p class=\"none\">none</p>\n";
    return;
  }
  html << "<table>\n<tr><th>test</th><th>old</th><th>new</th></tr>\n";
  for (const auto& row : rows)
    html << "<tr><td>" << escapeText(row.test) << "</td>" << verdictCell(row.oldVerdict) << verdictCell(row.newVerdict)
         << "</tr>\n";
  html << "</table>\n";
}

void listTable(std::ostream& html, std::string_view id, std::string_view title, const std::vector<ListedTest>& rows) {
  html << "<h2 id=\"" << id << "\">" << escapeText(title) << " (" << rows.size() << ")</h2>\n";
  if (rows.empty()) {
    html << "<p class=\"none\">none</p>\n";
    return;
  }
  html << "<table>\n<tr><th>test</th><th>verdict</th></tr>\n";
  for (const auto& row : rows) html << "<tr><td>" << escapeText(row.test) << "</td>" << verdictCell(row.verdict) << "</tr>\n";
  html << "</table>\n";
}

void runMeta(std::ostream& html, std::string_view heading, std::string_view label, const results::RunRecord& run,
             std::size_t tests) {
  html << "<h3>" << escapeText(heading) << "</h3>\n<dl class=\"meta\">\n";
  html << "<dt>file</dt><dd>" << escapeText(label) << "</dd>\n";
  for (const auto& [key, value] : {std::pair{"started_utc", &run.startedUtc},
                                   std::pair{"lightcts_revision", &run.lightctsRevision},
                                   std::pair{"command", &run.command}})
    html << "<dt>" << key << "</dt><dd>" << escapeText(*value) << "</dd>\n";
  html << "<dt>tests</dt><dd>" << tests << "</dd>\n</dl>\n";
}

}  // namespace

bool RunComparison::unchanged() const {
  return regressions.empty() && fixes.empty() && changes.empty() && added.empty() && removed.empty() &&
         tightness.empty();
}


RunComparison compareRuns(const results::RunRecord& oldRun, const results::RunRecord& newRun) {
  const TestIndex before = indexTests(oldRun);
  const TestIndex after = indexTests(newRun);
  RunComparison c;
  c.oldTests = before.order.size();
  c.newTests = after.order.size();
  for (const std::string& name : after.order) {
    const TestView& now = after.byName.at(name);
    const auto old = before.byName.find(name);
    if (old == before.byName.end()) {
      c.added.push_back({name, now.verdict});
      continue;
    }
    const TestView& then = old->second;
    const bool failedBefore = then.runFailure;
    const bool failsNow = now.runFailure;
    if (!failedBefore && failsNow)
      c.regressions.push_back({name, then.verdict, now.verdict});
    else if (failedBefore && !failsNow)
      c.fixes.push_back({name, then.verdict, now.verdict});
    else if (then.verdict != now.verdict)
      c.changes.push_back({name, then.verdict, now.verdict});
    if (then.tightness && now.tightness && beyondTwice(*then.tightness, *now.tightness))
      c.tightness.push_back({name, *then.tightness, *now.tightness});
  }
  for (const std::string& name : before.order)
    if (!after.byName.contains(name)) c.removed.push_back({name, before.byName.at(name).verdict});
  return c;
}

void printRunComparison(const RunComparison& c, std::string_view oldLabel, std::string_view newLabel,
                        std::ostream& out) {
  out << "run compare: " << oldLabel << " (" << c.oldTests << " tests) -> " << newLabel << " (" << c.newTests
      << " tests)\n";
  for (const auto& r : c.regressions)
    out << "REGRESSION " << r.test << ": " << shownVerdict(r.oldVerdict) << " -> " << shownVerdict(r.newVerdict) << "\n";
  for (const auto& r : c.fixes)
    out << "fix " << r.test << ": " << shownVerdict(r.oldVerdict) << " -> " << shownVerdict(r.newVerdict) << "\n";
  for (const auto& r : c.changes)
    out << "changed " << r.test << ": " << shownVerdict(r.oldVerdict) << " -> " << shownVerdict(r.newVerdict) << "\n";
  for (const auto& t : c.added) out << "new " << t.test << ": " << shownVerdict(t.verdict) << "\n";
  for (const auto& t : c.removed) out << "removed " << t.test << ": was " << shownVerdict(t.verdict) << "\n";
  for (const auto& t : c.tightness)
    out << "tightness " << t.test << ": " << formatNumber(t.oldTightness) << " -> " << formatNumber(t.newTightness) << " ("
        << ratioText(t.oldTightness, t.newTightness) << ")\n";
  if (c.unchanged())
    out << "no change\n";
  else
    out << summaryLine(c) << "\n";
}

std::string runComparisonHtml(const RunComparison& c, const results::RunRecord& oldRun,
                              const results::RunRecord& newRun, std::string_view oldLabel, std::string_view newLabel) {
  std::ostringstream html;
  html::pageStart(html, "lightcts run comparison", kPageStyle);
  html << "<h1>lightcts run comparison</h1>\n";
  runMeta(html, "old run", oldLabel, oldRun, c.oldTests);
  runMeta(html, "new run", newLabel, newRun, c.newTests);
  html << "<h2>Summary</h2>\n";
  if (c.unchanged()) html << "<p><strong>no change</strong></p>\n";
  html << "<table>\n<tr><th>kind</th><th>tests</th></tr>\n";
  const auto countRow = [&](std::string_view id, std::string_view kind, std::size_t n, bool bad = false) {
    html << "<tr" << (bad && n ? " class=\"regression\"" : "") << "><th><a href=\"#" << id << "\">" << kind
         << "</a></th><td class=\"n\">" << n << "</td></tr>\n";
  };
  countRow("regressions", "regressions", c.regressions.size(), true);
  countRow("fixes", "fixes", c.fixes.size());
  countRow("changes", "other changes", c.changes.size());
  countRow("new", "new tests", c.added.size());
  countRow("removed", "removed tests", c.removed.size());
  countRow("tightness", "tightness beyond 2x", c.tightness.size());
  html << "</table>\n";
  changeTable(html, "regressions", "Regressions", c.regressions);
  changeTable(html, "fixes", "Fixes", c.fixes);
  changeTable(html, "changes", "Other changes", c.changes);
  listTable(html, "new", "New tests", c.added);
  listTable(html, "removed", "Removed tests", c.removed);
  html << "<h2 id=\"tightness\">Tightness beyond 2x (" << c.tightness.size() << ")</h2>\n";
  if (c.tightness.empty()) {
    html << "<p class=\"none\">none</p>\n";
  } else {
    html << "<table>\n<tr><th>test</th><th>old</th><th>new</th><th>change</th></tr>\n";
    for (const auto& t : c.tightness)
      html << "<tr><td>" << escapeText(t.test) << "</td><td class=\"n\">" << formatNumber(t.oldTightness)
           << "</td><td class=\"n\">" << formatNumber(t.newTightness) << "</td><td class=\"n\">"
           << escapeText(ratioText(t.oldTightness, t.newTightness)) << "</td></tr>\n";
    html << "</table>\n";
  }
  html::pageEnd(html);
  return html.str();
}

std::filesystem::path writeRunComparisonHtml(const RunComparison& c, const results::RunRecord& oldRun,
                                             const results::RunRecord& newRun, std::string_view oldLabel,
                                             std::string_view newLabel, const std::filesystem::path& outDir) {
  std::filesystem::create_directories(outDir);
  const auto file = outDir / "index.html";
  imaging::writeFileAtomically(file, runComparisonHtml(c, oldRun, newRun, oldLabel, newLabel));
  return file;
}

}  // namespace reports
