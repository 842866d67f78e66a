#include "reports/csv_writer.h"

#include "comparison/verdict.h"
#include "imaging/atomic_file.h"
#include "reports/result_fields.h"

#include <optional>
#include <string_view>

namespace reports {
namespace {

// A field as RFC 4180 writes it: quoted only when it holds a comma, a quote
// or a line break (deqp-runner's names never do, nor do lightcts's in practice).
std::string csvField(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (const char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

// One line of text for a comment: the first line, control characters as
// spaces, trimmed.
std::string commentText(const std::string& text) {
  std::string line = text.substr(0, text.find_first_of("\r\n"));
  for (char& c : line)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = ' ';
  const auto first = line.find_first_not_of(' ');
  if (first == std::string::npos) return "";
  return line.substr(first, line.find_last_not_of(' ') - first + 1);
}

// Why the test failed, in one line: its message, else its failing pixels.
std::string reasonOf(const Json& test, std::string_view verdict) {
  std::string reason = commentText(textField(test, "message"));
  const Json& metrics = objectField(test, "metrics");
  if (reason.empty() && !metrics.empty())
    reason = formatField(metrics, "failing_pixels") + " failing of " + formatField(metrics, "compared_pixels") +
             " compared pixels, max error " + formatMetric(metrics, "max_abs_error");
  if (reason.empty()) reason = std::string(verdict) + " with no message";
  return reason;
}

}  // namespace

std::string resultsCsv(const Json& results) {
  checkResultsFormat(results);
  std::string text;
  for (const Json& test : arrayField(results, "tests")) {
    const std::string verdict = textField(test, "verdict");
    const double seconds = numberField(objectField(test, "timings_ms"), "total").value_or(0) / 1000.0;
    text += csvField(textField(test, "name")) + "," + csvField(verdict.empty() ? "unknown" : verdict) + "," +
            formatSeconds(seconds) + "\n";
  }
  return text;
}

std::string failuresCsv(const Json& results) {
  checkResultsFormat(results);
  std::string text = "# failures.csv of the lightcts run started " + textField(results, "started_utc") +
                     " (lightcts " + textField(results, "lightcts_revision") + ")\n" +
                     "# The run failures as expected failures: `lightcts run --expected-failures` reads this file\n" +
                     "# as it is. Copy it to seed a driver's list; replace each reason after '#' with the cause.\n";
  using comparison::Verdict;
  for (const Json& test : arrayField(results, "tests")) {
    const std::string name = textField(test, "name");
    const std::string verdictName = textField(test, "verdict");
    const std::optional<Verdict> verdict = comparison::parseVerdict(verdictName);
    if (verdict && !comparison::isRunFailure(*verdict)) continue;
    const std::string entry = name + "," + verdictName;
    if (!verdict) {  // results.json is not trusted: an unknown word is shown, never listed
      text += "# " + commentText(entry) + ": unknown verdict, not listed\n";
    } else if (*verdict == Verdict::UnexpectedPass) {
      text += "# " + commentText(entry) + ": passes now; remove its line from the expected-failures file (it was listed: " +
              commentText(textField(test, "expected_reason")) + ")\n";
    } else if (!comparison::isExpectable(*verdict)) {  // NotRun: the run was interrupted before it
      text += "# " + commentText(entry) + ": " + reasonOf(test, verdictName) +
              "; not listed, an expected-failures line cannot name " + verdictName + "\n";
    } else if (name.empty() || name.find_first_of(",#\r\n") != std::string::npos) {
      text += "# " + commentText(entry) +
              ": cannot be listed, an expected-failures file cannot hold a name with ',' or '#'\n";
    } else {
      text += entry + "  # " + reasonOf(test, verdictName) + "\n";
    }
  }
  return text;
}

void writeRunCsvs(const Json& results, const std::filesystem::path& dir) {
  imaging::writeFileAtomically(dir / "results.csv", resultsCsv(results));
  imaging::writeFileAtomically(dir / "failures.csv", failuresCsv(results));
}

}  // namespace reports
