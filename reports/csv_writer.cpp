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
std::string reasonOf(const results::TestRecord& test) {
  std::string reason = commentText(test.message);
  if (reason.empty() && test.metrics)
    reason = std::to_string(test.metrics->failingPixels) + " failing of " + std::to_string(test.metrics->comparedPixels) +
             " compared pixels, max error " + formatMeasured(test.metrics->maxAbsError);
  if (reason.empty()) reason = test.verdictWord() + " with no message";
  return reason;
}

}  // namespace

std::string resultsCsv(const results::RunRecord& run) {
  std::string text;
  for (const results::TestRecord& test : run.tests) {
    const double seconds = test.timingsMs ? test.timingsMs->total / 1000.0 : 0;
    text += csvField(test.name) + "," + csvField(test.verdictWord()) + "," +
            formatSeconds(seconds) + "\n";
  }
  return text;
}

std::string failuresCsv(const results::RunRecord& run) {
  std::string text = "# failures.csv of the lightcts run started " + run.startedUtc + " (lightcts " +
                     run.lightctsRevision + ")\n" +
                     "# The run failures as expected failures: `lightcts run --expected-failures` reads this file\n" +
                     "# as it is. Copy it to seed a driver's list; replace each reason after '#' with the cause.\n";
  using comparison::Verdict;
  for (const results::TestRecord& test : run.tests) {
    if (!comparison::isRunFailure(test.verdict)) continue;
    const std::string verdictName = test.verdictWord();
    const std::string entry = test.name + "," + verdictName;
    if (!test.knownVerdict()) {  // results.json is not trusted: an unknown word is shown, never listed
      text += "# " + commentText(entry) + ": unknown verdict, not listed\n";
    } else if (test.verdict == Verdict::UnexpectedPass) {
      text += "# " + commentText(entry) + ": passes now; remove its line from the expected-failures file (it was listed: " +
              commentText(test.expectedReason) + ")\n";
    } else if (!comparison::isExpectable(test.verdict)) {  // NotRun: the run was interrupted before it
      text += "# " + commentText(entry) + ": " + reasonOf(test) +
              "; not listed, an expected-failures line cannot name " + verdictName + "\n";
    } else if (test.name.empty() || test.name.find_first_of(",#\r\n") != std::string::npos) {
      text += "# " + commentText(entry) +
              ": cannot be listed, an expected-failures file cannot hold a name with ',' or '#'\n";
    } else {
      text += entry + "  # " + reasonOf(test) + "\n";
    }
  }
  return text;
}

void writeRunCsvs(const results::RunRecord& run, const std::filesystem::path& dir) {
  imaging::writeFileAtomically(dir / "results.csv", resultsCsv(run));
  imaging::writeFileAtomically(dir / "failures.csv", failuresCsv(run));
}

}  // namespace reports
