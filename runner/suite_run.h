// `lightcts run` (SPEC 8): every selected scene on every backend
// combination asked for, in worker processes (`lightcts worker`), so a driver
// crash or hang becomes that test's Crash or Timeout and the run goes on.
// Each combination's tests are split into parts (runner/run_plan.h), up to
// --jobs of them in workers at once; --shard I/N runs one of N disjoint
// shards of the run (`lightcts merge` joins them). Writes results.json
// (docs/results-format.md), junit.xml, results.csv, failures.csv and
// report/index.html under the output folder, prints progress per
// combination and a summary with the slowest tests.
#pragma once

#include "runner/run_plan.h"

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace runner {

struct RunOptions {
  std::vector<std::string> backends;  // combination suffixes or API names; empty: all
  std::string scenesDir = "suite/scenes";
  std::string outDir;
  std::string device;                 // --device for every backend
  std::string expectDriver;           // --expect-driver
  std::vector<std::string> expectedFailureFiles;
  std::string driver;                 // --driver: the GL combinations' Mesa driver; "" for the table's
  // The selection (runner/test_selection.h): --include, --exclude, --caselist.
  std::vector<std::string> includes;
  std::vector<std::string> excludes;
  std::vector<std::string> caselists;
  std::vector<std::string> mutants;   // --mutant: these only; empty: every mutant (unless noMutants)
  bool noMutants = false;             // --no-mutants
  bool noBudgets = false;             // --no-budgets: leave out the report's light budgets (SPEC 5.5)
  bool mutantsOnly = false;           // --mutants-only: the mutation check alone (ctest -L mutants)
  // --mutants-all-scenes: every mutant against every selected scene (the
  // whole kill table), not only against its killers (suite/mutant_killers.def).
  bool mutantsAllScenes = false;
  // --admissible: these admissible variants (SPEC 7), each against every
  // selected scene on every combination that realises it, as tests named
  // <group>.<name>@<variant>.<suffix>; "all" for every one. None by default.
  std::vector<std::string> admissible;
  bool admissibleOnly = false;        // --admissible-only: the variants' tests alone (no model test, no mutant)
  // --admissible-witnesses: each variant against its witnesses alone
  // (suite/admissible_witnesses.def), as ctest checks them.
  bool admissibleWitnesses = false;
  // --sharpness: each model test also bisects the smallest relative
  // brightness error its comparison catches (docs/tolerances.md "Sharpness").
  bool measureSharpness = false;
  int evidenceLimit = 50;             // --evidence-limit: failures that keep their images (all keep numbers)
  std::string evidenceUrl;            // --evidence-url: junit.xml's evidence link, "{test}" replaced
  bool listOnly = false;              // --list: print the selected tests (this shard's) and run nothing
  double timeoutSeconds = 120;        // per test
  int flakeRetries = 1;               // --flake-retries: re-runs of a failing, crashing or timed-out test
  bool flakesFail = false;            // --flakes-fail: a Flake fails the run
  int jobs = 0;                       // --jobs: worker processes at once; 0: one per core
  int testsPerWorker = int(kModelTestsPerPart);  // --tests-per-worker: a worker part's tasks (workerParts)
  std::optional<ShardSpec> shard;     // --shard I/N; none: the whole run
  std::string timingsFile;            // --timings: a results.json to balance the shards by
  // The shared reference cache folder (conformance/reference_cache.h). With
  // freshReferences, or when it is "", the run uses a cache of its own
  // (OUT/reference-cache, removed at the end): every reference is computed
  // in this run, once, and shared by its workers.
  std::string referenceCache;
  bool freshReferences = false;       // --fresh-references
  bool progressInPlace = false;       // stdout is a terminal: redraw the progress lines in place
  std::string workerExecutable;       // the lightcts binary (/proc/self/exe)
  std::string commandLine;            // for results.json
};

// A test whose raw verdict is Fail, Crash or Timeout, and not as its
// expected-failures line says, is re-run up to flakeRetries times in a fresh
// worker; one that then passes is Flake (docs/results-format.md).
// Exit status: 0 when every test that ran passed (or failed as expected, or
// was a Flake without flakesFail) and every mutant was killed (in a shard, a
// mutant that survives its shard's scenes fails only the merged run); 1
// otherwise; 3 when no backend was present; 128 + the signal (130, 143)
// when SIGINT or SIGTERM interrupted it (runner/run_interruption.h), with
// the outputs written for the tests that finished.
// Throws std::invalid_argument / scene_input::SceneLoadError / std::runtime_error
// for bad input (the caller maps them to exit 2).
int runSuite(const RunOptions& options, std::ostream& out, std::ostream& err);

}  // namespace runner
