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

const results::TestRecord* findTest(const results::RunRecord& run, const std::string& name) {
  for (const results::TestRecord& test : run.tests)
    if (test.name == name) return &test;
  return nullptr;
}

void metaRow(std::ostream& out, std::string_view term, std::string_view value) {
  out << "<dt>" << escapeText(term) << "</dt><dd>" << escapeText(value.empty() ? "-" : value) << "</dd>\n";
}

// The verdict columns of the backend table: every verdict that a table of
// counts always lists, and any other that occurred in this run.
std::vector<comparison::Verdict> verdictColumns(const results::RunRecord& run) {
  std::vector<comparison::Verdict> columns;
  for (const comparison::Verdict verdict : comparison::kAllVerdicts) {
    bool occurred = comparison::listedWhenZero(verdict);
    for (const results::BackendRecord& backend : run.backends) {
      const auto it = backend.counts.find(verdict);
      occurred = occurred || (it != backend.counts.end() && it->second > 0);
    }
    for (const results::TestRecord& test : run.tests)
      occurred = occurred || test.knownVerdict() == verdict;
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

std::string testLink(const results::TestRecord& test) {
  if (!test.needsAttention()) return escapeText(test.name);
  return "<a href=\"#" + escapeText(testAnchor(test.name)) + "\">" + escapeText(test.name) + "</a>";
}

std::string cell(std::string_view text) { return "<td>" + escapeText(text) + "</td>"; }
std::string numberCell(std::string_view text) { return "<td class=\"n\">" + escapeText(text) + "</td>"; }

void header(std::ostream& out, const Page& page) {
  const results::RunRecord& run = page.run;
  long long problems = 0, warnings = 0, skipped = 0, expected = 0, total = 0, survived = 0;
  for (const results::TestRecord& test : run.tests) {
    ++total;
    const Outcome outcome = test.ciOutcome();
    // An expected failure is a skip to CI (it must not block), but to a
    // reader it is a known defect of the driver, not a test that could not run.
    if (test.knownVerdict() == comparison::Verdict::QualityWarning) ++warnings;
    else if (test.knownVerdict() == comparison::Verdict::ExpectedFail) ++expected;
    else if (outcome == Outcome::Failure || outcome == Outcome::Error) ++problems;
    else if (outcome == Outcome::Skipped) ++skipped;
  }
  for (const results::MutantRecord& mutant : run.mutants)
    if (comparison::isRunFailure(mutant.status)) ++survived;
  long long brokenBackends = 0;
  for (const results::BackendRecord& backend : run.backends) brokenBackends += comparison::isRunFailure(backend.status);

  out << "<h1>lightcts conformance report</h1>\n<p><strong>";
  if (problems == 0 && survived == 0 && brokenBackends == 0)
    out << "No failures";
  else
    out << problems << " failing test" << (problems == 1 ? "" : "s") << ", " << survived << " mutant run"
        << (survived == 1 ? "" : "s") << " not killed, " << brokenBackends << " backend"
        << (brokenBackends == 1 ? "" : "s") << " with an error";
  out << "</strong> (" << total << " tests, " << warnings << " quality warnings, " << skipped << " skipped (not supported), "
      << expected << " expected failures)</p>\n<dl class=\"meta\">\n";
  metaRow(out, "revision", run.lightctsRevision);
  metaRow(out, "started (UTC)", run.startedUtc);
  metaRow(out, "duration", formatNumber(run.durationSeconds) + " s");
  metaRow(out, "command", run.command);
  metaRow(out, "machine", run.machine.hostname + ": " + run.machine.cpu + ", " + std::to_string(run.machine.cores) +
                              " cores, " + run.machine.os);
  metaRow(out, "scenes", run.scenesDir);
  metaRow(out, "timeout per test", formatOptional(run.timeoutSeconds) + " s");
  std::string chosen;
  for (const auto& [items, label] : {std::pair{&run.selection.include, "--include"},
                                     std::pair{&run.selection.exclude, "--exclude"},
                                     std::pair{&run.selection.caselists, "--caselist"}})
    for (const std::string& item : *items) {
      if (!chosen.empty()) chosen += ' ';
      chosen += label;
      chosen += ' ';
      chosen += item;
    }
  if (!chosen.empty()) metaRow(out, "selection", chosen);
  for (const results::BaselineFile& file : run.baselineFiles)
    metaRow(out, file.kind, file.path + " (SHA-256 " + file.sha256 + ")");
  out << "</dl>\n<p><a href=\"#backends\">backends</a> | <a href=\"#mutants\">mutants</a> | "
         "<a href=\"#attention\">tests that need attention</a> | <a href=\"#tests\">all tests</a> | "
         "<a href=\"#popping\">popping</a> | <a href=\"#slowest\">slowest tests</a></p>\n";
}

void backendSummary(std::ostream& out, const Page& page) {
  const results::RunRecord& run = page.run;
  out << "<h2 id=\"backends\">Backends</h2>\n<table class=\"summary\">\n<tr><th>backend</th><th>status</th><th>device</th>"
         "<th>driver</th><th>driver version</th><th>API</th>";
  const std::vector<comparison::Verdict> columns = verdictColumns(run);
  for (const comparison::Verdict verdict : columns)
    out << "<th>" << escapeText(comparison::verdictName(verdict)) << "</th>";
  out << "<th>wall s</th><th>expected failures</th><th>message</th></tr>\n";
  std::map<comparison::Verdict, long long> totals;
  for (const std::string& name : backendOrder(run)) {
    const results::BackendRecord* backend = nullptr;
    for (const results::BackendRecord& b : run.backends)
      if (b.backend == name) backend = &b;
    // A backend only its tests name: counted from them.
    std::map<comparison::Verdict, long long> counted;
    for (const results::TestRecord& test : run.tests)
      if (test.backend == name && test.admissible.empty()) ++counted[test.verdict];
    const results::DeviceRecord device =
        backend && backend->device ? *backend->device : results::DeviceRecord{};
    const std::string status =
        backend ? std::string(comparison::backendStatusName(backend->status)) : "not listed in backends";
    const bool ran = backend && backend->status == comparison::BackendStatus::Ran;
    out << "<tr>" << cell(name) << "<td>" << (ran ? escapeText(status) : verdictBadge(status)) << "</td>"
        << cell(device.name) << cell(device.driver) << cell(device.driverVersion) << cell(device.apiVersion);
    for (const comparison::Verdict column : columns) {
      long long n = counted[column];
      if (backend) {
        const auto it = backend->counts.find(column);
        n = it != backend->counts.end() ? it->second : 0;
      }
      totals[column] += n;
      const bool bad = n > 0 && comparison::needsAttention(column);
      out << "<td class=\"n" << (n == 0 ? " zero" : bad ? " bad" : "") << "\">" << n << "</td>";
    }
    out << numberCell(backend ? formatNumber(backend->wallSeconds) : "-")
        << cell(backend ? backend->expectedFailuresFile : "") << "<td>"
        << escapeText(backend ? backend->message : "");
    if (backend && !backend->log.empty())  // the backend's worker log, relative to the run folder
      out << (backend->message.empty() ? "" : " ") << linkTo(backend->log, page, "log");
    out << "</td></tr>\n";
  }
  out << "<tr><th colspan=\"6\">all backends</th>";
  for (const comparison::Verdict column : columns) out << "<td class=\"n\">" << totals[column] << "</td>";
  out << "<td colspan=\"3\"></td></tr>\n</table>\n";
}

void mutantTable(std::ostream& out, const Page& page) {
  const std::vector<results::MutantRecord>& mutants = page.run.mutants;
  out << "<h2 id=\"mutants\">Mutants</h2>\n";
  if (mutants.empty()) {
    out << "<p>No mutants in this run.</p>\n";
    return;
  }
  std::vector<std::string> names, backends;
  for (const results::MutantRecord& m : mutants)
    if (std::find(names.begin(), names.end(), m.mutant) == names.end()) names.push_back(m.mutant);
  for (const std::string& b : backendOrder(page.run))
    for (const results::MutantRecord& m : mutants)
      if (m.backend == b) {
        backends.push_back(b);
        break;
      }
  long long killed = 0;
  for (const results::MutantRecord& m : mutants) killed += m.status == comparison::MutantStatus::Killed;
  const std::string& check = page.run.mutantCheck;
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
    for (const results::MutantRecord& m : mutants)
      if (m.mutant == name && what.empty()) what = m.what;
    out << "<tr>" << cell(name) << cell(what);
    for (const std::string& b : backends) {
      const results::MutantRecord* found = nullptr;
      for (const results::MutantRecord& m : mutants)
        if (m.mutant == name && m.backend == b) found = &m;
      if (!found) {
        out << "<td class=\"zero\">not run</td>";
        continue;
      }
      out << "<td>" << verdictBadge(comparison::mutantStatusName(found->status));
      if (check == "killers" && found->status == comparison::MutantStatus::Survived)  // which scenes were meant to catch it
        out << "<br><small>missed by its killers: " << escapeText(joined(found->killers)) << "</small>";
      const std::string killers = joined(found->killedBy);
      if (found->killedBy.size() > 3)  // a long list folds away (plain HTML, no script)
        out << "<details><summary><small>by " << found->killedBy.size() << " scenes</small></summary><small>"
            << escapeText(killers) << "</small></details>";
      else if (!killers.empty())
        out << "<br><small>by " << escapeText(killers) << "</small>";
      if (const auto& evidence = found->evidence) {
        if (!evidence->errorMaskPng.empty()) {  // where the first killing scene caught it
          const std::string href = escapeText(imageHref(evidence->errorMaskPng, page.runDir, page.reportDir));
          out << "<br><a href=\"" << href << "\"><img class=\"thumb\" src=\"" << href << "\" alt=\"error mask: "
              << escapeText(evidence->errorMaskPng) << "\"></a>";
        }
        out << "<br><small>";
        if (!evidence->test.empty()) out << escapeText(evidence->test) << ": ";
        bool first = true;
        for (const auto& [path, label] : {std::pair{&evidence->viewer, "viewer"}, std::pair{&evidence->resultPng, "result"},
                                          std::pair{&evidence->referencePng, "reference"},
                                          std::pair{&evidence->errorMaskPng, "error mask"}})
          if (!path->empty()) {
            out << (first ? "" : " ") << linkTo(*path, page, label);
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
  const std::vector<results::MutantNotChecked>& notChecked = page.run.mutantsNotChecked;
  if (!notChecked.empty()) {
    out << "<p>" << notChecked.size() << " mutant" << (notChecked.size() == 1 ? " was" : "s were")
        << " not checked in this run:</p>\n<ul>\n";
    for (const results::MutantNotChecked& m : notChecked)
      out << "<li>" << escapeText(m.mutant) << ": " << escapeText(m.reason) << "</li>\n";
    out << "</ul>\n";
  }
}

void slowestTests(std::ostream& out, const Page& page) {
  const std::vector<results::SlowTest> rows = results::slowestTests(page.run.tests);
  out << "<h2 id=\"slowest\">Slowest tests</h2>\n";
  if (rows.empty()) {
    out << "<p>No timings in this run.</p>\n";
    return;
  }
  out << "<table>\n<tr><th>test</th><th>total ms</th>";
  for (const auto& [field, stage] : results::StageTimes::kFields)
    if (field != &results::StageTimes::total) out << "<th>" << stage << " ms</th>";
  out << "</tr>\n";
  for (const results::SlowTest& row : rows) {
    const results::TestRecord* test = findTest(page.run, row.name);
    out << "<tr><td>" << (test ? testLink(*test) : escapeText(row.name)) << "</td>"
        << numberCell(formatNumber(row.totalMs, 6));
    for (const auto& [field, stage] : results::StageTimes::kFields)
      if (field != &results::StageTimes::total)
        out << numberCell(test && test->timingsMs ? formatNumber((*test->timingsMs).*field, 6) : "-");
    out << "</tr>\n";
  }
  out << "</table>\n";
}

}  // namespace reports::html
