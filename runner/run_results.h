// The parts of results.json (docs/results-format.md) that `lightcts run` and
// `lightcts merge` both build, so a merged run reads exactly like one run.
#pragma once

#include "comparison/run_status.h"
#include "comparison/verdict.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace runner {

// A backend's "counts", in report order (zeros only where listedWhenZero).
nlohmann::ordered_json countsJson(const std::map<comparison::Verdict, int>& counted);
// A backend's "mutant_counts" from its mutant records: killed, survived, and
// "other" for the statuses that prove nothing.
nlohmann::ordered_json mutantCountsJson(const std::vector<const nlohmann::ordered_json*>& mutantRecords);
// The ten slowest tests by timings_ms.total, for results.json's "slowest".
nlohmann::ordered_json slowestTests(const nlohmann::ordered_json& tests);

// A digest of a scene folder's files (their relative paths and bytes, in
// catalogue order): two runs with the same digest ran the same scenes.
std::string scenesDigest(const std::vector<std::filesystem::path>& sceneFiles, const std::filesystem::path& root);

// Removes what an earlier run left in `outDir` that this one might not
// rewrite (evidence, mutants, report, results files, part and retry logs),
// so that nothing of it is mistaken for this run's.
void removeStaleRunOutputs(const std::filesystem::path& outDir);
// The report, junit.xml, results.csv and failures.csv, then results.json
// last: its presence says the run finished and the other files are complete.
void writeRunOutputs(const nlohmann::ordered_json& results, const std::filesystem::path& outDir);

}  // namespace runner
