// The rules of a result, written once: how the parts of a backend's run
// (worker parts in one run, or shards in a merge) combine into its status,
// what a mutant's status is, how verdicts and mutants are counted, and
// whether a run passes. `lightcts run` and `lightcts merge` both call them.
#pragma once

#include "results/run_records.h"

#include <string>
#include <string_view>
#include <vector>

namespace results {

struct StatusAndMessage {
  comparison::BackendStatus status = comparison::BackendStatus::Ran;
  std::string message;
};

// A backend over the parts of its run: Error when a part broke (its
// message), or when some part found the backend absent after another had it
// (`absentInSome` then prefixes the absent part's message); NotSupported
// only when every part found it absent; Ran otherwise.
StatusAndMessage combinedBackendStatus(const std::vector<StatusAndMessage>& parts, std::string_view absentInSome);

// What is known of a mutant on a backend, over its tasks (or over shards).
struct MutantObservations {
  bool killed = false;          // some scene that passes without it failed with it
  bool backendAbsent = false;   // its backend was NotSupported (in every shard)
  bool crashed = false;         // some task crashed
  bool timedOut = false;        // some task timed out
  bool notRun = false;          // some task was not run: the run was interrupted
};
// Killed, else NotSupported, else Crash, else Timeout, else NotRun, else
// Survived: a kill proves the check, and a run that did not finish proves nothing.
comparison::MutantStatus mutantStatus(const MutantObservations& seen);
// A mutant record's status as observations, so shards' records join.
MutantObservations observationsOf(comparison::MutantStatus status);
// The observations of two parts together.
MutantObservations joined(const MutantObservations& a, const MutantObservations& b);

// A model test's raw verdict passes (a QualityWarning included): it ends the
// retries, and it is the clean verdict a mutant's kill is judged against.
bool passed(comparison::Verdict raw);
// An attempt that failed, crashed or timed out: worth a retry (unless its
// expected-failures line says so), and the attempt a retried test's record shows.
bool failedAttempt(comparison::Verdict raw);

// The verdicts of `backend`'s model tests, of its admissible variants'
// tests, and its mutant records' statuses.
std::map<comparison::Verdict, int> countVerdicts(const std::vector<TestRecord>& tests, std::string_view backend);
std::map<comparison::Verdict, int> countAdmissibleVerdicts(const std::vector<TestRecord>& tests,
                                                           std::string_view backend);

// Each admissible variant on each backend over its tests, in the order the
// tests first show them: Unsound when a test is a run failure by a Fail,
// else Incomplete when one crashed, timed out or was not run, else NotSupported when
// every test was, else Sound. `run` and `merge` both derive them from the
// tests, so they cannot drift apart. `what` and `grant` are the table's
// (shaders/shader_interface.def), which the runner fills in.
std::vector<AdmissibleRecord> admissibleRecords(const std::vector<TestRecord>& tests);
MutantCounts countMutants(const std::vector<MutantRecord>& mutants, std::string_view backend);

// Whether `lightcts run` (or `merge`) exits 0: no test is a run failure (nor
// a Flake with flakes_fail; an admissible variant's test included), no
// backend is in error, and no mutant failed its check. In a shard a mutant that survived proves nothing yet: another
// shard may kill it, so only the merged run can say it survived.
bool runPasses(const RunRecord& run);

}  // namespace results
