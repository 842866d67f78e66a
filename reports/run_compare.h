// Comparing two runs (`lightcts run compare OLD NEW`): what changed
// from one results.json to the other, per test name, as piglit's summary
// comparison shows it. Both runs are records (results/results_file.h reads
// the files), and a verdict word no verdict has counts as a run failure.
#pragma once

#include "reports/result_fields.h"

#include <cstddef>
#include <filesystem>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace reports {

struct VerdictChange {
  std::string test;
  std::string oldVerdict;
  std::string newVerdict;
};

struct ListedTest {
  std::string test;
  std::string verdict;
};

struct TightnessChange {
  std::string test;
  double oldTightness = 0;
  double newTightness = 0;
};

struct RunComparison {
  std::size_t oldTests = 0;  // distinct named tests of each run
  std::size_t newTests = 0;
  std::vector<VerdictChange> regressions;  // not a run failure before, a run failure now
  std::vector<VerdictChange> fixes;        // a run failure before, not one now
  std::vector<VerdictChange> changes;      // any other change of verdict (Pass -> NotSupported, ...)
  std::vector<ListedTest> added;           // only in the new run
  std::vector<ListedTest> removed;         // only in the old run
  std::vector<TightnessChange> tightness;  // both finite, new/old > 2 or < 1/2
  bool unchanged() const;
};

// Tests are matched by name; a test without a name is ignored, and of two
// with one name the first counts. Lists follow the new run's order of tests
// (removed ones the old run's).
RunComparison compareRuns(const results::RunRecord& oldRun, const results::RunRecord& newRun);

// The printout: one line per regression, fix, other change, new test, removed
// test and tightness change, then a summary line; "no change" when unchanged.
void printRunComparison(const RunComparison& comparison, std::string_view oldLabel, std::string_view newLabel,
                        std::ostream& out);

// A self-contained HTML page (html_page.h's frame): both runs' metadata, a
// table of counts and one table per kind of change.
std::string runComparisonHtml(const RunComparison& comparison, const results::RunRecord& oldRun,
                              const results::RunRecord& newRun, std::string_view oldLabel, std::string_view newLabel);
// Writes outDir/index.html atomically, creating outDir; returns the file.
std::filesystem::path writeRunComparisonHtml(const RunComparison& comparison, const results::RunRecord& oldRun,
                                             const results::RunRecord& newRun, std::string_view oldLabel,
                                             std::string_view newLabel, const std::filesystem::path& outDir);

}  // namespace reports
