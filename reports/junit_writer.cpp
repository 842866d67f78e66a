#include "reports/junit_writer.h"

#include "imaging/atomic_file.h"
#include "reports/html_escape.h"
#include "reports/result_fields.h"

#include <algorithm>
#include <array>

#include <optional>
#include <sstream>
#include <utility>
#include <vector>

namespace reports {
namespace {

struct Case {
  std::string classname;
  std::string name;
  double seconds = 0;
  Outcome outcome = Outcome::Pass;
  std::string type;     // the verdict or status, on <failure>/<error>/<skipped>
  std::string message;  // one line, the attribute
  std::string details;  // the element text of <failure>/<error>
  std::string output;   // <system-out>
};

struct Suite {
  std::string name;
  std::vector<std::pair<std::string, std::string>> properties;
  std::vector<Case> cases;
  std::optional<double> seconds;  // the backend's wall time; else the sum of its cases
};

std::string lineOf(const std::string& text) {
  std::string line = text.substr(0, text.find('\n'));
  return line;
}

std::string metricsLine(const std::optional<results::Metrics>& metrics) {
  if (!metrics) return "";
  std::string text = std::to_string(metrics->failingPixels) + " failing of " + std::to_string(metrics->comparedPixels) +
                     " compared pixels";
  if (metrics->maxFailingPixels > 0) text += " (" + std::to_string(metrics->maxFailingPixels) + " allowed)";
  text += ", max error " + formatMeasured(metrics->maxAbsError) + ", tightness " + formatMeasured(metrics->tightness);
  if (metrics->nonFinitePixels > 0) text += ", " + std::to_string(metrics->nonFinitePixels) + " non-finite";
  return text;
}

// A channel that is none was not finite (results.json has no NaN or infinity).
std::string triple(const std::array<results::Measured, 3>& values) {
  std::string text = "(";
  for (std::size_t c = 0; c < values.size(); ++c)
    text += (c ? ", " : "") + (values[c] ? formatNumber(*values[c], 9) : std::string("non-finite"));
  return text + ")";
}

// Where a test's evidence page is: the viewer's path in the run folder, or
// --evidence-url's template with {test} replaced (a CI artifact's URL, as
// deqp-runner's `junit --template`). A failure past --evidence-limit has no
// images and no page: its numbers (summary.json) stand in. "" when none.
std::string evidencePage(const results::TestRecord& test, const std::string& urlTemplate) {
  if (!test.evidence) return "";
  if (test.evidence->viewer.empty()) return test.evidence->summaryJson;
  if (urlTemplate.empty()) return test.evidence->viewer;
  std::string url = urlTemplate;
  for (std::size_t at = url.find("{test}"); at != std::string::npos; at = url.find("{test}", at + test.name.size()))
    url.replace(at, 6, test.name);
  return url;
}

// Everything a person needs from a CI page without opening the HTML report.
std::string testDetails(const results::TestRecord& test, const std::string& page) {
  std::ostringstream out;
  if (!page.empty()) out << "evidence: " << page << '\n';
  if (!test.description.empty()) out << test.description << '\n';
  out << "scene file: " << test.sceneFile << '\n';
  out << "verdict: " << test.verdictWord() << " (raw: " << comparison::verdictName(test.rawVerdict) << ")\n";
  if (!test.expectedReason.empty()) out << "expected failure: " << test.expectedReason << '\n';
  if (!test.message.empty()) out << "message: " << test.message << '\n';
  if (test.metrics) {
    out << metricsLine(test.metrics) << '\n';
    for (const results::WorstPixel& pixel : test.metrics->worst)
      out << "  (" << pixel.x << ", " << pixel.y << ") result " << triple(pixel.result) << " reference "
          << triple(pixel.reference) << " tolerance " << triple(pixel.tolerance) << '\n';
  }
  if (test.frames)
    for (const results::FrameRecord& frame : *test.frames)
      if (frame.verdict != comparison::Verdict::Pass)
        out << "frame " << frame.frame << ": " << comparison::verdictName(frame.verdict) << ", " << frame.failingPixels
            << " failing, max error " << formatOptional(frame.maxAbsError) << '\n';
  if (test.evidence)
    for (const auto& [key, value] : {std::pair{"result_png", &test.evidence->resultPng},
                                     std::pair{"reference_png", &test.evidence->referencePng},
                                     std::pair{"error_mask_png", &test.evidence->errorMaskPng},
                                     std::pair{"summary_json", &test.evidence->summaryJson}})
      if (!value->empty()) out << key << ": " << *value << '\n';
  return out.str();
}

Case testCase(const results::TestRecord& test, const std::string& evidenceUrl) {
  Case c;
  const std::string page = evidencePage(test, evidenceUrl);
  const auto details = [&] { return testDetails(test, page); };
  c.classname = junitClassname(test.backend, test.group);
  c.name = test.name;
  if (c.name.empty()) c.name = test.group + "." + test.scene + "." + test.backend;
  c.seconds = test.timingsMs ? test.timingsMs->total / 1000.0 : 0;
  // An unknown word is reported like a Fail: a report never turns what it
  // does not know into a pass.
  c.outcome = test.ciOutcome();
  c.type = test.verdictWord();
  const std::string message = lineOf(test.message);
  const std::string metrics = metricsLine(test.metrics);
  const std::string& reason = test.expectedReason;
  using comparison::Verdict;
  switch (test.knownVerdict().value_or(Verdict::Fail)) {
    case Verdict::ExpectedFail:
      c.message = "ExpectedFail: " + (reason.empty() ? std::string("listed as an expected failure") : reason);
      c.output = details();
      break;
    case Verdict::UnexpectedPass:
      c.message = "UnexpectedPass: listed as an expected failure (" + reason + ") but passed; remove it from the list";
      c.details = details();
      break;
    case Verdict::NotSupported: c.message = "NotSupported" + (message.empty() ? "" : ": " + message); break;
    case Verdict::Pass: break;
    case Verdict::QualityWarning:  // skipped: the comparison checked nothing (SPEC 7)
      c.message = "QualityWarning: " + (message.empty() ? metrics : message);
      c.output = details();
      break;
    case Verdict::Flake:  // a pass, with the failure before the retry shown beside it
      c.output = "Flake: failed, then passed on a retry" + (message.empty() ? "" : ": " + message) + "\n" + details();
      break;
    case Verdict::Fail:
    case Verdict::Crash:
    case Verdict::Timeout:
      c.message = c.type + ": " + (message.empty() ? metrics : message);
      c.details = details();
      break;
    case Verdict::NotRun: c.message = "NotRun: " + message; break;  // the run was interrupted first
  }
  // Every failing testcase names its evidence page where CI pages show it first.
  if ((c.outcome == Outcome::Failure || c.outcome == Outcome::Error) && !page.empty())
    c.message += " (evidence: " + page + ")";
  return c;
}

Case mutantCase(const results::MutantRecord& mutant, const std::string& check) {
  Case c;
  const std::string status(comparison::mutantStatusName(mutant.status));
  c.classname = junitClassname(mutant.backend, "mutants");
  c.name = "mutants." + mutant.mutant + "." + mutant.backend;
  c.type = status;
  c.outcome = comparison::ciOutcome(mutant.status);
  const std::string killers = joined(mutant.killedBy);
  using comparison::MutantStatus;
  switch (mutant.status) {
    case MutantStatus::Killed: c.output = mutant.what + "\nkilled by: " + killers + "\n"; break;
    case MutantStatus::NotSupported: c.message = "NotSupported"; break;
    case MutantStatus::Crash:
    case MutantStatus::Timeout:
    case MutantStatus::NotRun:
      c.message = status + ": the mutant's run did not finish; it proves nothing (" + mutant.what + ")";
      break;
    case MutantStatus::Survived:
      if (check == "killers") {
        c.message = "survived: its killers (" + joined(mutant.killers) +
                    ") did not catch this wrong variant of the model (" + mutant.what + ")";
      } else {
        c.message = "survived: no scene caught this wrong variant of the model (" + mutant.what + ")";
      }
      break;
  }
  return c;
}

// <testsuites> carries no `skipped`: the JUnit schema that Jenkins validates
// with (reports/tests/junit.xsd) allows it on <testsuite> only.
std::string openTag(const char* tag, const Suite& suite, std::string_view extra = "") {
  const bool root = std::string_view(tag) == "testsuites";
  int failures = 0, errors = 0, skipped = 0;
  double seconds = 0;
  for (const Case& c : suite.cases) {
    failures += c.outcome == Outcome::Failure;
    errors += c.outcome == Outcome::Error;
    skipped += c.outcome == Outcome::Skipped;
    seconds += c.seconds;
  }
  std::string text = "<" + std::string(tag) + " name=\"" + escapeXmlAttribute(suite.name) + "\" tests=\"" +
                     std::to_string(suite.cases.size()) + "\" failures=\"" + std::to_string(failures) +
                     "\" errors=\"" + std::to_string(errors) + "\"" +
                     (root ? std::string() : " skipped=\"" + std::to_string(skipped) + "\"") + " time=\"" +
                     formatSeconds(suite.seconds.value_or(seconds)) + "\"";
  return text + std::string(extra) + ">\n";
}

void writeCase(std::ostringstream& out, const Case& c) {
  out << "    <testcase classname=\"" << escapeXmlAttribute(c.classname) << "\" name=\"" << escapeXmlAttribute(c.name)
      << "\" time=\"" << formatSeconds(c.seconds) << "\"";
  if (c.outcome == Outcome::Pass && c.output.empty()) {
    out << "/>\n";
    return;
  }
  out << ">\n";
  const auto problem = [&](const char* tag) {
    out << "      <" << tag << " message=\"" << escapeXmlAttribute(c.message) << "\" type=\""
        << escapeXmlAttribute(c.type) << "\">" << escapeText(c.details) << "</" << tag << ">\n";
  };
  if (c.outcome == Outcome::Failure) problem("failure");
  if (c.outcome == Outcome::Error) problem("error");
  if (c.outcome == Outcome::Skipped)
    out << "      <skipped message=\"" << escapeXmlAttribute(c.message) << "\" type=\"" << escapeXmlAttribute(c.type)
        << "\"/>\n";
  if (!c.output.empty()) out << "      <system-out>" << escapeText(c.output) << "</system-out>\n";
  out << "    </testcase>\n";
}

std::vector<Suite> suites(const results::RunRecord& run) {
  std::vector<Suite> list;
  for (const std::string& backendName : backendOrder(run)) {
    Suite suite;
    suite.name = backendName;
    const auto backend = std::find_if(run.backends.begin(), run.backends.end(),
                                      [&](const results::BackendRecord& b) { return b.backend == backendName; });
    if (backend != run.backends.end()) {
      const results::DeviceRecord device = backend->device.value_or(results::DeviceRecord{});
      for (const auto& [key, value] : {std::pair{"name", &device.name}, std::pair{"driver", &device.driver},
                                       std::pair{"driver_version", &device.driverVersion},
                                       std::pair{"api_version", &device.apiVersion}})
        suite.properties.emplace_back(std::string("device.") + key, *value);
      suite.properties.emplace_back("api_backend", backend->apiBackend);
      suite.properties.emplace_back("driver_option", backend->driverOption);
      suite.properties.emplace_back("status", std::string(comparison::backendStatusName(backend->status)));
      suite.properties.emplace_back("message", backend->message);
      suite.properties.emplace_back("expected_failures_file", backend->expectedFailuresFile);
      suite.seconds = backend->wallSeconds;
    }
    for (const results::TestRecord& test : run.tests)
      if (test.backend == backendName) suite.cases.push_back(testCase(test, run.evidenceUrl));
    if (backend != run.backends.end() && suite.cases.empty() && backend->status != comparison::BackendStatus::Ran) {
      Case c;
      c.classname = junitClassname(backendName, "backend");
      c.name = "backend." + backendName;
      c.type = std::string(comparison::backendStatusName(backend->status));
      c.outcome = comparison::ciOutcome(backend->status);
      c.message = c.type + (backend->message.empty() ? "" : ": " + backend->message);
      suite.cases.push_back(c);
    }
    if (!suite.cases.empty() || !suite.properties.empty()) list.push_back(std::move(suite));
  }
  if (!run.mutants.empty()) {
    Suite mutants;
    mutants.name = "mutants";
    for (const results::MutantRecord& mutant : run.mutants) mutants.cases.push_back(mutantCase(mutant, run.mutantCheck));
    list.push_back(std::move(mutants));
  }
  return list;
}

}  // namespace

std::string junitClassname(std::string_view backend, std::string_view group) {
  if (backend.empty()) return std::string(group);
  if (group.empty()) return std::string(backend);
  return std::string(backend) + "." + std::string(group);
}

std::string junitXml(const results::RunRecord& run) {
  const std::vector<Suite> list = suites(run);
  Suite all;
  all.name = "lightcts";
  all.seconds = run.durationSeconds;
  for (const Suite& suite : list) all.cases.insert(all.cases.end(), suite.cases.begin(), suite.cases.end());

  std::ostringstream out;
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n" << openTag("testsuites", all);
  for (const Suite& suite : list) {
    std::string extra;
    if (!run.startedUtc.empty()) extra += " timestamp=\"" + escapeXmlAttribute(run.startedUtc) + "\"";
    if (!run.machine.hostname.empty()) extra += " hostname=\"" + escapeXmlAttribute(run.machine.hostname) + "\"";
    out << "  " << openTag("testsuite", suite, extra);
    out << "    <properties>\n";
    out << "      <property name=\"lightcts_revision\" value=\"" << escapeXmlAttribute(run.lightctsRevision)
        << "\"/>\n";
    for (const auto& [name, value] : suite.properties)
      out << "      <property name=\"" << escapeXmlAttribute(name) << "\" value=\"" << escapeXmlAttribute(value)
          << "\"/>\n";
    out << "    </properties>\n";
    for (const Case& c : suite.cases) writeCase(out, c);
    out << "  </testsuite>\n";
  }
  out << "</testsuites>\n";
  return out.str();
}

void writeJunit(const results::RunRecord& run, const std::filesystem::path& file) {
  imaging::writeFileAtomically(file, junitXml(run));
}

}  // namespace reports
