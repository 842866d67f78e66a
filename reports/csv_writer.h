// results.csv and failures.csv of a run (docs/results-format.md): the two
// lists Mesa's deqp-runner writes beside its results, made from the run's records.
//
// results.csv   every test, one `test,Verdict,seconds` line each, in
//               results.json's order (deqp-runner's results.csv: name, status,
//               duration); no header, no comments.
// failures.csv  the run failures only (comparison::isRunFailure), one
//               `test,Verdict  # reason` line each: the expected-failures
//               format of runner/expected_failures.h, so that the file loads
//               with `lightcts run --expected-failures failures.csv` as it is
//               and a vendor seeds a driver's list by copying it. The reason is
//               the test's message (its first line), or the failing pixels.
//               An UnexpectedPass is a comment line instead (it passes now:
//               its line leaves the list), and so is a test whose name an
//               expected-failures file cannot hold (a ',' or '#' in it).
// Mutants are in neither (results.json and junit.xml list them): their
// statuses are not verdicts, and no expected-failures file lists them.
#pragma once

#include "results/run_records.h"

#include <filesystem>
#include <string>

namespace reports {

// The text of results.csv.
std::string resultsCsv(const results::RunRecord& run);

// The text of failures.csv: a header of comment lines, then the failures.
std::string failuresCsv(const results::RunRecord& run);

// Both files in `dir` (results.csv, failures.csv), each written atomically.
void writeRunCsvs(const results::RunRecord& run, const std::filesystem::path& dir);

}  // namespace reports
