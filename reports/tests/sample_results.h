// A small hand-written results.json (docs/results-format.md) with one of
// every verdict, a backend that did not run, mutants killed and not, an
// animated scene, and text that needs escaping. Used by the unit tests and by
// make_sample_run, which also writes the PNG files it names.
#pragma once

#include "results/run_records.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace reports::testing {

nlohmann::ordered_json sampleResults();

// A results.json read into records, as every report reads a run.
inline results::RunRecord records(const nlohmann::ordered_json& results) { return results::RunRecord::fromJson(results); }
inline results::RunRecord sampleRun() { return records(sampleResults()); }

// Every PNG path (relative to the run folder) that sampleResults names.
std::vector<std::string> samplePngPaths(const nlohmann::ordered_json& results);

}  // namespace reports::testing
