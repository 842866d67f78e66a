#include "reports/junit_writer.h"

#include "imaging/atomic_file.h"
#include "reports/html_escape.h"
#include "reports/result_fields.h"

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

std::string metricsLine(const Json& metrics) {
  if (metrics.empty()) return "";
  std::string text = formatField(metrics, "failing_pixels") + " failing of " + formatField(metrics, "compared_pixels") +
                     " compared pixels";
  if (numberField(metrics, "max_failing_pixels").value_or(0) > 0)
    text += " (" + formatField(metrics, "max_failing_pixels") + " allowed)";
  text += ", max error " + formatMetric(metrics, "max_abs_error") + ", tightness " + formatMetric(metrics, "tightness");
  if (numberField(metrics, "non_finite_pixels").value_or(0) > 0)
    text += ", " + formatField(metrics, "non_finite_pixels") + " non-finite";
  return text;
}

// Null in a result means NaN or infinity (results.json has neither).
std::string triple(const Json& pixel, std::string_view key) {
  const Json& values = arrayField(pixel, key);
  std::string text = "(";
  for (std::size_t c = 0; c < values.size(); ++c)
    text += (c ? ", " : "") + (values[c].is_null() ? "non-finite" : formatValue(values[c], 9));
  return text + ")";
}

// Where a test's evidence page is: the viewer's path in the run folder, or
// --evidence-url's template with {test} replaced (a CI artifact's URL, as
// deqp-runner's `junit --template`). A failure past --evidence-limit has no
// images and no page: its numbers (summary.json) stand in. "" when none.
std::string evidencePage(const Json& test, const std::string& urlTemplate) {
  const Json& evidence = objectField(test, "evidence");
  const std::string viewer = textField(evidence, "viewer");
  if (viewer.empty()) return textField(evidence, "summary_json");
  if (urlTemplate.empty()) return viewer;
  std::string url = urlTemplate;
  const std::string name = textField(test, "name");
  for (std::size_t at = url.find("{test}"); at != std::string::npos; at = url.find("{test}", at + name.size()))
    url.replace(at, 6, name);
  return url;
}

// Everything a person needs from a CI page without opening the HTML report.
std::string testDetails(const Json& test, const std::string& page) {
  std::ostringstream out;
  if (!page.empty()) out << "evidence: " << page << '\n';
  const Json& metrics = objectField(test, "metrics");
  if (!textField(test, "description").empty()) out << textField(test, "description") << '\n';
  out << "scene file: " << textField(test, "scene_file") << '\n';
  out << "verdict: " << textField(test, "verdict") << " (raw: " << textField(test, "raw_verdict") << ")\n";
  if (!textField(test, "expected_reason").empty()) out << "expected failure: " << textField(test, "expected_reason") << '\n';
  if (!textField(test, "message").empty()) out << "message: " << textField(test, "message") << '\n';
  if (!metrics.empty()) out << metricsLine(metrics) << '\n';
  for (const Json& pixel : arrayField(metrics, "worst"))
    out << "  (" << formatField(pixel, "x") << ", " << formatField(pixel, "y") << ") result " << triple(pixel, "result")
        << " reference " << triple(pixel, "reference") << " tolerance " << triple(pixel, "tolerance") << '\n';
  for (const Json& frame : arrayField(test, "frames"))
    if (comparison::parseVerdict(textField(frame, "verdict")) != comparison::Verdict::Pass)
      out << "frame " << formatField(frame, "frame") << ": " << textField(frame, "verdict") << ", "
          << formatField(frame, "failing_pixels") << " failing, max error " << formatField(frame, "max_abs_error") << '\n';
  const Json& evidence = objectField(test, "evidence");
  for (const char* key : {"result_png", "reference_png", "error_mask_png", "summary_json"})
    if (!textField(evidence, key).empty()) out << key << ": " << textField(evidence, key) << '\n';
  return out.str();
}

Case testCase(const Json& test, const std::string& evidenceUrl) {
  Case c;
  const std::string page = evidencePage(test, evidenceUrl);
  const auto testDetails = [&](const Json& t) { return reports::testDetails(t, page); };
  const std::string verdict = textField(test, "verdict");
  const std::string group = textField(test, "group");
  c.classname = junitClassname(textField(test, "backend"), group);
  c.name = textField(test, "name");
  if (c.name.empty()) c.name = group + "." + textField(test, "scene") + "." + textField(test, "backend");
  c.seconds = numberField(objectField(test, "timings_ms"), "total").value_or(0) / 1000.0;
  c.outcome = outcomeOf(verdict);
  c.type = verdict.empty() ? "unknown" : verdict;
  const std::string message = lineOf(textField(test, "message"));
  const std::string metrics = metricsLine(objectField(test, "metrics"));
  const std::string reason = textField(test, "expected_reason");
  using comparison::Verdict;
  // An unknown verdict is reported like a Fail (outcomeOf made it a Failure).
  switch (comparison::parseVerdict(verdict).value_or(Verdict::Fail)) {
    case Verdict::ExpectedFail:
      c.message = "ExpectedFail: " + (reason.empty() ? std::string("listed as an expected failure") : reason);
      c.output = testDetails(test);
      break;
    case Verdict::UnexpectedPass:
      c.message = "UnexpectedPass: listed as an expected failure (" + reason + ") but passed; remove it from the list";
      c.details = testDetails(test);
      break;
    case Verdict::NotSupported: c.message = "NotSupported" + (message.empty() ? "" : ": " + message); break;
    case Verdict::Pass: break;
    case Verdict::QualityWarning:  // skipped: the comparison checked nothing (SPEC 7)
      c.message = "QualityWarning: " + (message.empty() ? metrics : message);
      c.output = testDetails(test);
      break;
    case Verdict::Flake:  // a pass, with the failure before the retry shown beside it
      c.output = "Flake: failed, then passed on a retry" + (message.empty() ? "" : ": " + message) + "\n" +
                 testDetails(test);
      break;
    case Verdict::Fail:
    case Verdict::Crash:
    case Verdict::Timeout:
      c.message = c.type + ": " + (message.empty() ? metrics : message);
      c.details = testDetails(test);
      break;
    case Verdict::NotRun: c.message = "NotRun: " + message; break;  // the run was interrupted first
  }
  // Every failing testcase names its evidence page where CI pages show it first.
  if ((c.outcome == Outcome::Failure || c.outcome == Outcome::Error) && !page.empty())
    c.message += " (evidence: " + page + ")";
  return c;
}

Case mutantCase(const Json& mutant, const std::string& check) {
  Case c;
  const std::string status = textField(mutant, "status");
  const std::string name = textField(mutant, "mutant");
  c.classname = junitClassname(textField(mutant, "backend"), "mutants");
  c.name = "mutants." + name + "." + textField(mutant, "backend");
  c.type = status.empty() ? "unknown" : status;
  const std::string killers = joinedField(mutant, "killed_by");
  const std::string what = textField(mutant, "what");
  c.outcome = mutantOutcome(status);
  using comparison::MutantStatus;
  const std::optional<MutantStatus> known = comparison::parseMutantStatus(status);
  if (!known) {
    c.message = "unknown mutant status \"" + status + "\"";
    return c;
  }
  switch (*known) {
    case MutantStatus::Killed: c.output = what + "\nkilled by: " + killers + "\n"; break;
    case MutantStatus::NotSupported: c.message = "NotSupported"; break;
    case MutantStatus::Crash:
    case MutantStatus::Timeout:
    case MutantStatus::NotRun:
      c.message = status + ": the mutant's run did not finish; it proves nothing (" + what + ")";
      break;
    case MutantStatus::Survived:
      if (check == "killers") {
        c.message = "survived: its killers (" + joinedField(mutant, "killers") + ") did not catch this wrong variant of the model (" + what + ")";
      } else {
        c.message = "survived: no scene caught this wrong variant of the model (" + what + ")";
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

std::vector<Suite> suites(const Json& results) {
  std::vector<Suite> list;
  const std::string evidenceUrl = textField(results, "evidence_url");
  for (const std::string& backendName : backendOrder(results)) {
    Suite suite;
    suite.name = backendName;
    for (const Json& backend : arrayField(results, "backends")) {
      if (textField(backend, "backend") != backendName) continue;
      const Json& device = objectField(backend, "device");
      for (const char* key : {"name", "driver", "driver_version", "api_version"})
        suite.properties.emplace_back(std::string("device.") + key, textField(device, key));
      for (const char* key : {"api_backend", "driver_option", "status", "message", "expected_failures_file"})
        suite.properties.emplace_back(key, textField(backend, key));
      suite.seconds = numberField(backend, "wall_s");
      for (const Json& test : arrayField(results, "tests"))
        if (textField(test, "backend") == backendName) suite.cases.push_back(testCase(test, evidenceUrl));
      const std::string status = textField(backend, "status");
      const bool ran = comparison::parseBackendStatus(status) == comparison::BackendStatus::Ran;
      if (suite.cases.empty() && !ran) {
        Case c;
        c.classname = junitClassname(backendName, "backend");
        c.name = "backend." + backendName;
        c.type = status.empty() ? "unknown" : status;
        c.outcome = backendOutcome(status);
        c.message = c.type + (textField(backend, "message").empty() ? "" : ": " + textField(backend, "message"));
        suite.cases.push_back(c);
      }
      break;
    }
    if (suite.properties.empty())  // a backend that only tests name
      for (const Json& test : arrayField(results, "tests"))
        if (textField(test, "backend") == backendName) suite.cases.push_back(testCase(test, evidenceUrl));
    if (!suite.cases.empty() || !suite.properties.empty()) list.push_back(std::move(suite));
  }
  if (!arrayField(results, "mutants").empty()) {
    Suite mutants;
    mutants.name = "mutants";
    for (const Json& mutant : arrayField(results, "mutants"))
      mutants.cases.push_back(mutantCase(mutant, textField(results, "mutant_check")));
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

std::string junitXml(const Json& results) {
  checkResultsFormat(results);
  const std::vector<Suite> list = suites(results);
  Suite all;
  all.name = "lightcts";
  all.seconds = numberField(results, "duration_s");
  for (const Suite& suite : list) all.cases.insert(all.cases.end(), suite.cases.begin(), suite.cases.end());

  std::ostringstream out;
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n" << openTag("testsuites", all);
  const std::string timestamp = textField(results, "started_utc");
  const std::string hostname = textField(objectField(results, "machine"), "hostname");
  for (const Suite& suite : list) {
    std::string extra;
    if (!timestamp.empty()) extra += " timestamp=\"" + escapeXmlAttribute(timestamp) + "\"";
    if (!hostname.empty()) extra += " hostname=\"" + escapeXmlAttribute(hostname) + "\"";
    out << "  " << openTag("testsuite", suite, extra);
    out << "    <properties>\n";
    out << "      <property name=\"lightcts_revision\" value=\""
        << escapeXmlAttribute(textField(results, "lightcts_revision")) << "\"/>\n";
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

void writeJunit(const Json& results, const std::filesystem::path& file) {
  imaging::writeFileAtomically(file, junitXml(results));
}

}  // namespace reports
