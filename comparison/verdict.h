// The one definition of a test's verdict (SPEC 7, docs/results-format.md):
// the names results.json writes, their order in reports, and what each means
// to a run, to CI and to a person reading the report. Writers and readers of
// results.json call these functions instead of comparing strings, so a new
// verdict is added here and nowhere else.
#pragma once

#include <array>
#include <optional>
#include <ostream>
#include <string_view>

namespace comparison {

// SPEC 7's verdicts, then the two that a list of expected failures makes of
// them (runner/expected_failures.h), then Flake: a test that failed and then
// passed on a retry, and NotRun: a test an interrupted run (SIGINT, SIGTERM)
// never finished. A comparison yields only Pass or Fail; the others are
// decided by whoever runs the backend (missing driver, crash, hang, signal).
enum class Verdict {
  Pass, Fail, QualityWarning, NotSupported, Crash, Timeout, ExpectedFail, UnexpectedPass, Flake, NotRun
};

// Every verdict, in the order reports list them.
inline constexpr std::array<Verdict, 10> kAllVerdicts = {
    Verdict::Pass,  Verdict::Fail,    Verdict::QualityWarning, Verdict::NotSupported,  Verdict::Crash,
    Verdict::Timeout, Verdict::ExpectedFail, Verdict::UnexpectedPass, Verdict::Flake, Verdict::NotRun};

// Exactly SPEC 7's words: "Pass", "Fail", "QualityWarning", ...
std::string_view verdictName(Verdict verdict);
// The inverse of verdictName; anything else (other case, spaces) is nullopt.
std::optional<Verdict> parseVerdict(std::string_view name);
std::ostream& operator<<(std::ostream& out, Verdict verdict);  // its name

// A verdict that makes `lightcts run` (or `merge`) exit 1: Fail, Crash,
// Timeout, UnexpectedPass, and NotRun (a run that did not finish proves
// nothing). A QualityWarning, a skip, a known failure and a flake (it passed
// in the end) do not.
bool isRunFailure(Verdict verdict);

// What a verdict means to CI, in JUnit's four kinds (reports/junit_writer.h).
enum class CiOutcome { Pass, Failure, Error, Skipped };
CiOutcome ciOutcome(Verdict verdict);

// Whether the HTML report gives the test a section with its evidence: every
// run failure but NotRun (which has none), and the passes a person should
// still look at (QualityWarning, Flake).
bool needsAttention(Verdict verdict);

// The raw verdicts an expected-failures line may name (the failing verdicts
// of SPEC 7; NotSupported is a skip already and never needs listing).
bool isExpectable(Verdict verdict);

// Whether a table of counts per verdict (results.json "counts", the report's
// backend table) lists this verdict when none occurred. Flake came after
// results.json version 1: it is listed only when it occurred, so the counts
// of a run without retries are what they were; NotRun likewise (only an
// interrupted run has it).
bool listedWhenZero(Verdict verdict);

}  // namespace comparison
