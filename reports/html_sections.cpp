#include "reports/html_escape.h"
#include "reports/html_sections.h"
#include "reports/image_links.h"

#include <algorithm>
#include <map>
#include <vector>

namespace reports::html {
namespace {

std::string linkTo(std::string_view runRelative, const Page& page, std::string_view label) {
  const std::string href = imageHref(runRelative, page.runDir, page.reportDir);
  return "<a href=\"" + escapeText(href) + "\">" + escapeText(label) + "</a>";
}

const Json* findTest(const Json& results, const std::string& name) {
  for (const Json& test : arrayField(results, "tests"))
    if (textField(test, "name") == name) return &test;
  return nullptr;
}

void metaRow(std::ostream& out, std::string_view term, std::string_view value) {
  out << "<dt>" << escapeText(term) << "</dt><dd>" << escapeText(value.empty() ? "-" : value) << "</dd>\n";
}

// The verdict columns of the backend table: every verdict that a table of
// counts always lists, and any other that occurred in this run.
std::vector<comparison::Verdict> verdictColumns(const Json& results) {
  std::vector<comparison::Verdict> columns;
  for (const comparison::Verdict verdict : comparison::kAllVerdicts) {
    const std::string name(comparison::verdictName(verdict));
    bool occurred = comparison::listedWhenZero(verdict);
    for (const Json& backend : arrayField(results, "backends")) {
      const Json& counts = objectField(backend, "counts");
      occurred = occurred || (counts.contains(name) && counts[name].is_number_integer() && counts[name] > 0);
    }
    for (const Json& test : arrayField(results, "tests")) occurred = occurred || textField(test, "verdict") == name;
    if (occurred) columns.push_back(verdict);
  }
  return columns;
}

}  // namespace

std::string verdictBadge(std::string_view verdict) {
  // The word becomes a CSS class only when it is a verdict or a mutant status.
  const bool isKnown = comparison::parseVerdict(verdict) || comparison::parseMutantStatus(verdict);
  return "<span class=\"v v-" + std::string(isKnown ? verdict : "unknown") + "\">" +
         escapeText(verdict.empty() ? "unknown" : verdict) + "</span>";
}

std::string testAnchor(std::string_view testName) { return "test-" + percentEncodePath(testName); }

std::string testLink(const Json& test) {
  const std::string name = textField(test, "name");
  if (!needsAttention(textField(test, "verdict"))) return escapeText(name);
  return "<a href=\"#" + escapeText(testAnchor(name)) + "\">" + escapeText(name) + "</a>";
}

std::string cell(std::string_view text) { return "<td>" + escapeText(text) + "</td>"; }
std::string numberCell(std::string_view text) { return "<td class=\"n\">" + escapeText(text) + "</td>"; }

void header(std::ostream& out, const Page& page) {
  const Json& results = page.results;
  long long problems = 0, warnings = 0, skipped = 0, expected = 0, total = 0, survived = 0;
  for (const Json& test : arrayField(results, "tests")) {
    const std::string verdict = textField(test, "verdict");
    ++total;
    // An expected failure is a skip to CI (it must not block), but to a
    // reader it is a known defect of the driver, not a test that could not run.
    if (comparison::parseVerdict(verdict) == comparison::Verdict::QualityWarning) ++warnings;
    else if (comparison::parseVerdict(verdict) == comparison::Verdict::ExpectedFail) ++expected;
    else if (outcomeOf(verdict) == Outcome::Failure || outcomeOf(verdict) == Outcome::Error) ++problems;
    else if (outcomeOf(verdict) == Outcome::Skipped) ++skipped;
  }
  for (const Json& mutant : arrayField(results, "mutants"))
    if (mutantFailed(textField(mutant, "status"))) ++survived;
  long long brokenBackends = 0;
  for (const Json& backend : arrayField(results, "backends"))
    brokenBackends += backendFailed(textField(backend, "status"));

  out << "<h1>lightcts conformance report</h1>\n<p><strong>";
  if (problems == 0 && survived == 0 && brokenBackends == 0)
    out << "No failures";
  else
    out << problems << " failing test" << (problems == 1 ? "" : "s") << ", " << survived << " mutant run"
        << (survived == 1 ? "" : "s") << " not killed, " << brokenBackends << " backend"
        << (brokenBackends == 1 ? "" : "s") << " with an error";
  out << "</strong> (" << total << " tests, " << warnings << " quality warnings, " << skipped << " skipped (not supported), "
      << expected << " expected failures)</p>\n<dl class=\"meta\">\n";
  metaRow(out, "revision", textField(results, "lightcts_revision"));
  metaRow(out, "started (UTC)", textField(results, "started_utc"));
  metaRow(out, "duration", formatField(results, "duration_s") + " s");
  metaRow(out, "command", textField(results, "command"));
  const Json& machine = objectField(results, "machine");
  metaRow(out, "machine", textField(machine, "hostname") + ": " + textField(machine, "cpu") + ", " +
                              textField(machine, "cores") + " cores, " + textField(machine, "os"));
  metaRow(out, "scenes", textField(results, "scenes_dir"));
  metaRow(out, "timeout per test", formatField(results, "timeout_s") + " s");
  const Json& selection = objectField(results, "selection");
  std::string chosen;
  for (const auto& [key, label] : {std::pair{"include", "--include"}, std::pair{"exclude", "--exclude"},
                                   std::pair{"caselists", "--caselist"}})
    for (const Json& item : arrayField(selection, key)) {
      if (!chosen.empty()) chosen += ' ';
      chosen += label;
      chosen += ' ';
      chosen += formatValue(item);
    }
  if (!chosen.empty()) metaRow(out, "selection", chosen);
  for (const Json& file : arrayField(results, "baseline_files"))
    metaRow(out, textField(file, "kind"), textField(file, "path") + " (SHA-256 " + textField(file, "sha256") + ")");
  out << "</dl>\n<p><a href=\"#backends\">backends</a> | <a href=\"#mutants\">mutants</a> | "
         "<a href=\"#attention\">tests that need attention</a> | <a href=\"#tests\">all tests</a> | "
         "<a href=\"#popping\">popping</a> | <a href=\"#slowest\">slowest tests</a></p>\n";
}

void backendSummary(std::ostream& out, const Page& page) {
  out << "<h2 id=\"backends\">Backends</h2>\n<table class=\"summary\">\n<tr><th>backend</th><th>status</th><th>device</th>"
         "<th>driver</th><th>driver version</th><th>API</th>";
  const std::vector<comparison::Verdict> columns = verdictColumns(page.results);
  for (const comparison::Verdict verdict : columns)
    out << "<th>" << escapeText(comparison::verdictName(verdict)) << "</th>";
  out << "<th>wall s</th><th>expected failures</th><th>message</th></tr>\n";
  std::map<std::string, long long> totals;
  for (const std::string& name : backendOrder(page.results)) {
    const Json* backend = nullptr;
    for (const Json& b : arrayField(page.results, "backends"))
      if (textField(b, "backend") == name) backend = &b;
    const Json& entry = backend ? *backend : Json::object();
    std::map<std::string, long long> counted;
    for (const Json& test : arrayField(page.results, "tests"))
      if (textField(test, "backend") == name) ++counted[textField(test, "verdict")];
    const Json& counts = objectField(entry, "counts");
    const Json& device = objectField(entry, "device");
    const std::string status = backend ? textField(entry, "status") : "not listed in backends";
    const bool ran = comparison::parseBackendStatus(status) == comparison::BackendStatus::Ran;
    out << "<tr>" << cell(name) << "<td>" << (ran ? escapeText(status) : verdictBadge(status)) << "</td>"
        << cell(textField(device, "name")) << cell(textField(device, "driver"))
        << cell(textField(device, "driver_version")) << cell(textField(device, "api_version"));
    for (const comparison::Verdict column : columns) {
      const std::string verdict(comparison::verdictName(column));
      const long long n = counts.contains(verdict) && counts[verdict].is_number_integer()
                              ? counts[verdict].get<long long>()
                              : counted[verdict];
      totals[verdict] += n;
      const bool bad = n > 0 && comparison::needsAttention(column);
      out << "<td class=\"n" << (n == 0 ? " zero" : bad ? " bad" : "") << "\">" << n << "</td>";
    }
    out << numberCell(formatField(entry, "wall_s")) << cell(textField(entry, "expected_failures_file")) << "<td>"
        << escapeText(textField(entry, "message"));
    if (!textField(entry, "log").empty())  // optional: the backend's worker log, relative to the run folder
      out << (textField(entry, "message").empty() ? "" : " ") << linkTo(textField(entry, "log"), page, "log");
    out << "</td></tr>\n";
  }
  out << "<tr><th colspan=\"6\">all backends</th>";
  for (const comparison::Verdict column : columns)
    out << "<td class=\"n\">" << totals[std::string(comparison::verdictName(column))] << "</td>";
  out << "<td colspan=\"3\"></td></tr>\n</table>\n";
}

void mutantTable(std::ostream& out, const Page& page) {
  const Json& mutants = arrayField(page.results, "mutants");
  out << "<h2 id=\"mutants\">Mutants</h2>\n";
  if (mutants.empty()) {
    out << "<p>No mutants in this run.</p>\n";
    return;
  }
  std::vector<std::string> names, backends;
  for (const Json& m : mutants) {
    if (std::find(names.begin(), names.end(), textField(m, "mutant")) == names.end())
      names.push_back(textField(m, "mutant"));
  }
  for (const std::string& b : backendOrder(page.results))
    for (const Json& m : mutants)
      if (textField(m, "backend") == b) {
        backends.push_back(b);
        break;
      }
  long long killed = 0;
  for (const Json& m : mutants)
    killed += comparison::parseMutantStatus(textField(m, "status")) == comparison::MutantStatus::Killed;
  const std::string check = textField(page.results, "mutant_check");
  out << "<p>" << killed << " of " << mutants.size()
      << " mutant runs killed. A mutant is a deliberately wrong variant of the model (SPEC 7); "
         "it is killed when at least one scene fails with it. "
      << (check == "all-scenes" ? "This run checked each mutant against every selected scene (the whole kill table)."
          : check == "killers"  ? "This run checked each mutant against its killers, the scenes meant to catch it "
                                  "(suite/mutant_killers.def); --mutants-all-scenes checks every scene."
                                : "")
      << "</p>\n<table>\n<tr><th>mutant</th><th>what</th>";
  for (const std::string& b : backends) out << "<th>" << escapeText(b) << "</th>";
  out << "</tr>\n";
  for (const std::string& name : names) {
    std::string what;
    for (const Json& m : mutants)
      if (textField(m, "mutant") == name && what.empty()) what = textField(m, "what");
    out << "<tr>" << cell(name) << cell(what);
    for (const std::string& b : backends) {
      const Json* found = nullptr;
      for (const Json& m : mutants)
        if (textField(m, "mutant") == name && textField(m, "backend") == b) found = &m;
      if (!found) {
        out << "<td class=\"zero\">not run</td>";
        continue;
      }
      out << "<td>" << verdictBadge(textField(*found, "status"));
      if (check == "killers" && comparison::parseMutantStatus(textField(*found, "status")) ==
                                    comparison::MutantStatus::Survived) {  // which scenes were meant to catch it
        out << "<br><small>missed by its killers: " << escapeText(joinedField(*found, "killers")) << "</small>";
      }
      const Json& killedBy = arrayField(*found, "killed_by");
      const std::string killers = joinedField(*found, "killed_by");
      if (killedBy.size() > 3)  // a long list folds away (plain HTML, no script)
        out << "<details><summary><small>by " << killedBy.size() << " scenes</small></summary><small>"
            << escapeText(killers) << "</small></details>";
      else if (!killers.empty())
        out << "<br><small>by " << escapeText(killers) << "</small>";
      const Json& evidence = objectField(*found, "evidence");
      const std::string mask = textField(evidence, "error_mask_png");
      if (!mask.empty()) {  // where the first killing scene caught it
        const std::string href = escapeText(imageHref(mask, page.runDir, page.reportDir));
        out << "<br><a href=\"" << href << "\"><img class=\"thumb\" src=\"" << href << "\" alt=\"error mask: "
            << escapeText(mask) << "\"></a>";
      }
      if (!evidence.empty()) {
        out << "<br><small>";
        if (!textField(evidence, "test").empty()) out << escapeText(textField(evidence, "test")) << ": ";
        bool first = true;
        for (const auto& [key, label] : {std::pair{"viewer", "viewer"}, std::pair{"result_png", "result"},
                                         std::pair{"reference_png", "reference"}, std::pair{"error_mask_png", "error mask"}})
          if (!textField(evidence, key).empty()) {
            out << (first ? "" : " ") << linkTo(textField(evidence, key), page, label);
            first = false;
          }
        out << "</small>";
      }
      out << "</td>";
    }
    out << "</tr>\n";
  }
  out << "</table>\n";
  // A mutation check left out is said on the page, not only on the console.
  const Json& notChecked = arrayField(page.results, "mutants_not_checked");
  if (!notChecked.empty()) {
    out << "<p>" << notChecked.size() << " mutant" << (notChecked.size() == 1 ? " was" : "s were")
        << " not checked in this run:</p>\n<ul>\n";
    for (const Json& m : notChecked)
      out << "<li>" << escapeText(textField(m, "mutant")) << ": " << escapeText(textField(m, "reason")) << "</li>\n";
    out << "</ul>\n";
  }
}

void slowestTests(std::ostream& out, const Page& page) {
  struct Row {
    std::string name;
    Json totalMs;
  };
  std::vector<Row> rows;
  for (const Json& s : arrayField(page.results, "slowest")) {
    const auto it = s.find("total_ms");
    rows.push_back({textField(s, "name"), it != s.end() ? *it : Json()});
  }
  if (rows.empty()) {  // results without "slowest": the ten slowest tests
    for (const Json& test : arrayField(page.results, "tests"))
      if (numberField(objectField(test, "timings_ms"), "total"))
        rows.push_back({textField(test, "name"), objectField(test, "timings_ms")["total"]});
    std::stable_sort(rows.begin(), rows.end(),
                     [](const Row& a, const Row& b) { return a.totalMs.get<double>() > b.totalMs.get<double>(); });
    if (rows.size() > 10) rows.resize(10);
  }
  out << "<h2 id=\"slowest\">Slowest tests</h2>\n";
  if (rows.empty()) {
    out << "<p>No timings in this run.</p>\n";
    return;
  }
  const char* stages[] = {"reference", "pipeline", "draw", "readback", "compare"};
  out << "<table>\n<tr><th>test</th><th>total ms</th>";
  for (const char* stage : stages) out << "<th>" << stage << " ms</th>";
  out << "</tr>\n";
  for (const Row& row : rows) {
    const Json* test = findTest(page.results, row.name);
    const Json& timings = test ? objectField(*test, "timings_ms") : Json::object();
    out << "<tr><td>" << (test ? testLink(*test) : escapeText(row.name)) << "</td>"
        << numberCell(formatValue(row.totalMs, 6));
    for (const char* stage : stages) out << numberCell(formatField(timings, stage, 6));
    out << "</tr>\n";
  }
  out << "</table>\n";
}

}  // namespace reports::html
