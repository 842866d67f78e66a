// The HTML report of a run (its records, results/run_records.h): one page,
// plain HTML with a small inline style sheet, no JavaScript and nothing
// external except the run's own PNG images, linked by relative paths.
#pragma once

#include "results/run_records.h"

#include <filesystem>
#include <string>

namespace reports {

// The page, in this order: header (revision, date, machine, duration,
// command); per backend the counts of each verdict, device, driver and wall
// time; the mutant kill table (mutant x backend, killed_by scenes, a
// thumbnail of the error mask of the first killing scene); a section
// per test that needs attention (Fail, Crash, Timeout, UnexpectedPass,
// QualityWarning, unknown verdicts) with the result, reference and error-mask
// images side by side, its numbers, worst pixels with allowed bounds and
// message; a table of every test; per-frame popping tables of animated
// scenes; the slowest tests.
//
// Image paths in the records are relative to `runDir` (the run's --out
// folder); the page links them relative to `reportDir`, where it will live.
std::string htmlReport(const results::RunRecord& run, const std::filesystem::path& runDir,
                       const std::filesystem::path& reportDir);

// Writes outDir/index.html atomically (temporary file, then rename),
// creating outDir. The run folder is `runDir`, by default outDir's parent
// (`lightcts run --out OUT` writes OUT/report/index.html).
void writeHtmlReport(const results::RunRecord& run, const std::filesystem::path& outDir,
                     const std::filesystem::path& runDir = {});

}  // namespace reports
