// The one reader of a results.json file that a person hands lightcts (`run
// --timings`, `run compare`, `merge`'s shards): the file read into typed
// records (results/run_records.h), or refused with a message that names the
// file and what is wrong with it, never a crash on a hand-edited file.
//
// Refused: a file that cannot be read, is not JSON, is not a lightcts
// results.json ("format"), or lacks a key every results.json has had since
// version 1: "tests" and "backends" (arrays of objects), each test's "name",
// "backend" and "verdict", each backend's "backend" and "status"; and a
// record of "mutants", "admissible" or a test's "attempts" that is no
// object. The message names the key as a JSON path (`tests[3].name`). Tolerated, as
// docs/results-format.md promises: the keys later versions added (missing:
// their defaults), a word no verdict or status has (read as what
// RunRecord::fromJson makes of it), and keys lightcts does not know.
#pragma once

#include "results/run_records.h"

#include <filesystem>
#include <stdexcept>
#include <string>

namespace results {

class ResultsFileError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// Throws ResultsFileError "FILE: what".
RunRecord readResultsFile(const std::filesystem::path& file);

}  // namespace results
