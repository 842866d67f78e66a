// What `lightcts run` and `lightcts merge` both do around results.json
// (results/run_records.h): the scene set's digest, clearing a folder of an
// earlier run's files, and writing the run's files.
#pragma once

#include "results/run_records.h"

#include <filesystem>
#include <string>
#include <vector>

namespace runner {

// A digest of a scene folder's files (their relative paths and bytes, in
// catalogue order): two runs with the same digest ran the same scenes.
std::string scenesDigest(const std::vector<std::filesystem::path>& sceneFiles, const std::filesystem::path& root);

// A backend's counts for the console, as `run` and `merge` print them after
// its status: ", 161 Pass, 12 ExpectedFail; mutants: 33 killed, 0 survived"
// (the mutants only when the run checked some).
std::string backendCounts(const results::BackendRecord& backend, bool mutantsChecked);

// The admissible variants' summary: per backend, how many were sound, and
// each variant that was not with its failed tests ("run: admissible: vulkan:
// 15 variant(s) sound over 2460 test(s)" / "run: admissible: vulkan:
// quotient-up unsound: a.b@quotient-up.vulkan").
// results::admissibleRecords of `tests`, with each variant's `what` and
// `grant` from shaders/shader_interface.def.
std::vector<results::AdmissibleRecord> describedAdmissibleRecords(const std::vector<results::TestRecord>& tests);

std::vector<std::string> admissibleLines(const std::vector<results::AdmissibleRecord>& records);

// Removes what an earlier run left in `outDir` that this one might not
// rewrite (evidence, mutants, report, results files, part and retry logs),
// so that nothing of it is mistaken for this run's.
void removeStaleRunOutputs(const std::filesystem::path& outDir);
// The report, junit.xml, results.csv and failures.csv, then results.json
// last: its presence says the run finished and the other files are complete.
void writeRunOutputs(const results::RunRecord& run, const std::filesystem::path& outDir);

}  // namespace runner
