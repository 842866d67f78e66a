// `lightcts run` (SPEC 8, issue 6): every scene on every backend combination
// asked for, each combination in worker processes (`lightcts worker`), so a
// driver crash or hang becomes that test's Crash or Timeout and the run goes
// on. Writes results.json (docs/results-format.md), junit.xml and
// report/index.html under the output folder, and prints a summary with the
// slowest tests.
#pragma once

#include <iosfwd>
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
  std::vector<std::string> mutants;   // --mutant: these only; empty: every mutant (unless noMutants)
  bool noMutants = false;             // --no-mutants
  bool mutantsOnly = false;           // --mutants-only: the mutation check alone (ctest -L mutants)
  double timeoutSeconds = 120;        // per test
  int flakeRetries = 1;               // --flake-retries: re-runs of a failing, crashing or timed-out test
  bool flakesFail = false;            // --flakes-fail: a Flake fails the run
  std::string workerExecutable;       // the lightcts binary (/proc/self/exe)
  std::string commandLine;            // for results.json
};

// A test whose raw verdict is Fail, Crash or Timeout, and not as its
// expected-failures line says, is re-run up to flakeRetries times in a fresh
// worker; one that then passes is Flake (docs/results-format.md).
// Exit status: 0 when every test that ran passed (or failed as expected, or
// was a Flake without flakesFail) and every mutant was killed; 1 otherwise;
// 3 when no backend was present.
// Throws std::invalid_argument / lighting::SceneLoadError / std::runtime_error
// for bad input (the caller maps them to exit 2).
int runSuite(const RunOptions& options, std::ostream& out, std::ostream& err);

}  // namespace runner
