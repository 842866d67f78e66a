#include "runner/suite_run.h"

#include "results/result_rules.h"
#include "results/run_records.h"
#include "runner/evidence_limit.h"
#include "runner/run_assembly.h"
#include "runner/run_budgets.h"
#include "runner/run_execution.h"
#include "runner/run_inputs.h"
#include "runner/run_interruption.h"
#include "runner/run_metadata.h"
#include "runner/run_results.h"
#include "runner/run_units.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iomanip>
#include <ostream>
#include <set>
#include <sstream>

namespace runner {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

std::string formatMs(double ms) {
  std::ostringstream text;
  text << std::fixed << std::setprecision(ms < 10 ? 2 : 0) << ms << " ms";
  return text.str();
}

// SPEC 5.5 for the report: once per scene this run (or shard) holds,
// whatever the backends; mutant-only runs check no scene of their own.
std::vector<results::SceneBudgetRecord> lightBudgets(const RunOptions& options, const RunInputs& inputs, const RunUnits& plan, const fs::path& outDir,
                  std::vector<std::string>& summary) {
  // An interrupted run writes what it has, and budgets it has not computed.
  if (options.noBudgets || options.mutantsOnly || interruptingSignal() != 0) return {};
  const auto started = Clock::now();
  std::set<std::string> heldCases;
  for (const RunUnit& unit : plan.units) heldCases.insert(unit.test.substr(0, unit.test.rfind('.')));
  std::vector<BudgetScene> budgetScenes;
  for (const CatalogueEntry& scene : inputs.catalogue)
    if (heldCases.contains(scene.file.caseName())) budgetScenes.push_back({scene.file.caseName(), scene.file.path});
  std::vector<results::SceneBudgetRecord> budgets = runBudgets(budgetScenes, outDir);
  summary.push_back("run: light budgets of " + std::to_string(budgetScenes.size()) + " scene(s) in " +
                    formatMs(std::chrono::duration<double, std::milli>(Clock::now() - started).count()));
  return budgets;
}

// One line per combination: its status, its verdicts, its mutants, its time.
std::string backendLine(const results::BackendRecord& backend, bool mutantsChecked) {
  std::ostringstream line;
  line << "run: " << backend.backend << ": " << backend.status;
  if (!backend.message.empty()) line << " (" << backend.message << ")";
  line << backendCounts(backend, mutantsChecked) << " (" << std::fixed << std::setprecision(1) << backend.wallSeconds
       << " s in workers)";
  return line.str();
}

void printSummary(const RunOptions& options, const results::RunRecord& run, const AssembledRecords& records,
                  const std::vector<std::string>& budgetLines, long long imagesDropped, const fs::path& outDir,
                  std::ostream& out) {
  for (const results::BackendRecord& backend : run.backends) out << backendLine(backend, !run.mutantsRun.empty()) << "\n";
  for (const std::string& line : admissibleLines(run.admissible)) out << line << "\n";
  for (const std::string& line : budgetLines) out << line << "\n";
  // Flakes apart: they passed, so the per-backend lines alone would hide them.
  if (!records.flakes.empty()) {
    out << "flaky tests (failed, then passed on a retry in a fresh worker; "
        << (options.flakesFail ? "--flakes-fail: they fail this run" : "they fail a run only with --flakes-fail")
        << "):\n";
    for (const std::string& flake : records.flakes) out << "  " << flake << "\n";
  }
  if (imagesDropped > 0)
    out << "run: " << imagesDropped << " failure(s) past --evidence-limit " << options.evidenceLimit
        << " keep their numbers (summary.json) but no images\n";
  out << "slowest tests:\n";
  for (const results::SlowTest& s : results::slowestTests(run.tests))
    out << "  " << formatMs(s.totalMs) << "  " << s.name << "\n";
  out << "run: results in " << (outDir / "results.json").string() << ", report in "
      << (outDir / "report" / "index.html").string() << std::endl;
}

}  // namespace

int runSuite(const RunOptions& options, std::ostream& out, std::ostream& err) {
  const auto started = Clock::now();
  const std::string startedUtc = utcTimestamp();
  const RunInputs inputs = checkRunInputs(options);
  // --list keeps stdout for test names alone, so that it reads back as a caselist.
  const RunUnits plan = planRunUnits(options, inputs, options.listOnly ? err : out);
  if (options.listOnly) {
    listRunUnits(plan, out, err);
    return 0;
  }

  const InterruptionGuard interruption;
  const fs::path outDir(options.outDir);
  fs::create_directories(outDir / "logs");
  removeStaleRunOutputs(outDir);
  const bool privateCache = options.freshReferences || options.referenceCache.empty();
  const fs::path referenceCache =
      privateCache ? fs::absolute(outDir / "reference-cache") : fs::path(options.referenceCache);
  if (privateCache) fs::remove_all(referenceCache);
  const std::vector<CombinationRun> runs = executeRun(options, inputs, plan, {outDir, referenceCache}, out);
  if (privateCache) fs::remove_all(referenceCache);

  AssembledRecords records = assembleRecords(inputs, plan, runs);
  std::vector<std::string> budgetLines;
  results::RunRecord run;
  run.budgets = lightBudgets(options, inputs, plan, outDir, budgetLines);
  const long long imagesDropped = limitEvidenceImages(records.tests, outDir, options.evidenceLimit);
  std::vector<fs::path> sceneFiles;
  for (const CatalogueEntry& scene : inputs.catalogue) sceneFiles.push_back(scene.file.path);
  run.lightctsRevision = revision();
  run.startedUtc = startedUtc;
  run.command = options.commandLine;
  run.machine = thisMachine();
  run.scenesDir = options.scenesDir;
  run.scenesDigest = scenesDigest(sceneFiles, options.scenesDir);
  run.selection = inputs.selection.record();
  // Every file that decided how this run was judged or chosen.
  for (const std::string& file : options.expectedFailureFiles)
    run.baselineFiles.push_back(baselineFile("expected-failures", file));
  for (const std::string& file : options.caselists) run.baselineFiles.push_back(baselineFile("caselist", file));
  for (const shaders::Mutant mutant : plan.mutants) run.mutantsRun.emplace_back(shaders::mutantName(mutant));
  run.mutantCheck = options.mutantsAllScenes ? "all-scenes" : "killers";
  run.mutantsNotChecked = plan.mutantsNotChecked;
  run.evidenceLimit = options.evidenceLimit;
  run.evidenceUrl = options.evidenceUrl;
  run.jobs = inputs.jobs;
  run.shard = plan.shard;
  run.referenceCache = privateCache ? std::string("fresh") : referenceCache.string();
  run.timeoutSeconds = options.timeoutSeconds;
  run.flakeRetries = options.flakeRetries;
  run.flakesFail = options.flakesFail;
  run.tests = std::move(records.tests);
  run.backends = std::move(records.backends);
  run.mutants = std::move(records.mutants);
  run.admissible = describedAdmissibleRecords(run.tests);
  run.durationSeconds = std::chrono::duration<double>(Clock::now() - started).count();
  writeRunOutputs(run, outDir);
  printSummary(options, run, records, budgetLines, imagesDropped, outDir, out);

  if (const int signal = interruptingSignal(); signal != 0) {
    const auto notRun = std::count_if(run.tests.begin(), run.tests.end(), [](const results::TestRecord& t) {
      return t.verdict == comparison::Verdict::NotRun;
    });
    err << "lightcts: run: interrupted by " << signalName(signal) << ": " << run.tests.size() - notRun
        << " test(s) finished, " << notRun << " NotRun; exit status " << interruptedExitStatus(signal) << "\n";
    return interruptedExitStatus(signal);
  }

  if (options.shard && plan.units.empty()) {  // a small selection cut into many shards
    out << "run: shard " << options.shard->index << "/" << options.shard->total
        << " holds no test of this selection" << std::endl;
    return 0;
  }
  const bool anyPresent = std::any_of(run.backends.begin(), run.backends.end(), [](const results::BackendRecord& b) {
    return b.status != comparison::BackendStatus::NotSupported;  // an error is present, and fails
  });
  if (!anyPresent) {
    err << "lightcts: run: no backend asked for is present here (NotSupported)\n";
    return 3;
  }
  return results::runPasses(run) ? 0 : 1;
}

}  // namespace runner
