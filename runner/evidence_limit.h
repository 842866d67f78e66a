// `run --evidence-limit N`: at most N failing tests keep their evidence
// images (result, reference, tolerance, error mask, the viewer's data), so a
// driver that fails everything does not fill the disk or a CI artifact;
// every failure keeps its numbers (summary.json: the failing count, the
// worst pixels with their values and allowed bounds).
#pragma once

#include "results/run_records.h"

#include <filesystem>

namespace runner {

// Over a run's test records, in order: the run failures first
// (comparison::isRunFailure of the verdict), then the other tests with
// evidence (expected failures, detected expect_fail mismatches). Past the
// first `limit`, removes every file of the test's evidence folder but
// summary.json and rewrites its "evidence" to {"frame", "summary_json",
// "images_kept": false}. Returns how many lost their images. The mutation
// check's evidence (one folder per mutant and combination) is not counted.
long long limitEvidenceImages(std::vector<results::TestRecord>& tests, const std::filesystem::path& outDir, int limit);

}  // namespace runner
