// results.json's records (docs/results-format.md), typed: a worker's result
// for one task, a test, a backend, a mutant on a backend and the run around
// them, each with one reader and one writer. `lightcts run` assembles them
// from its workers' results; `lightcts merge` reads them back from each
// shard and joins them; both write through the same writers, so a merged
// run has the keys of one run in the same order; the reports read them.
// What nothing reads (a merge's list of its shards) is carried as JSON.
#pragma once

#include "comparison/run_status.h"
#include "comparison/verdict.h"
#include "results/budget_records.h"
#include "results/outcome_records.h"

#include <nlohmann/json.hpp>

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace results {

using Json = nlohmann::ordered_json;

// The worker protocol's "result" event (runner/suite_worker.h) without its
// kind and index: what one task of a worker plan came to.
struct TaskResult : TaskOutcome {
  std::string test;  // <group>.<name>.<suffix>
  // Workers write only verdictName's words; a result with none (or any
  // other) is from a worker that broke: it reads as a Crash.
  comparison::Verdict rawVerdict = comparison::Verdict::Crash;

  Json toJson() const;
  static TaskResult fromJson(const Json& json);
  // What a task that never got a worker's result (a crash, a timeout, a
  // backend that went away) is recorded as: its outcome all null
  // (docs/results-format.md), but the message.
  static TaskResult abnormal(const std::string& test, comparison::Verdict verdict, const std::string& message);
};

// One attempt of a test that was retried (flake detection).
struct AttemptRecord {
  comparison::Verdict rawVerdict = comparison::Verdict::Crash;
  std::string message;
  std::string log;  // relative to the run folder

  Json toJson() const;
  static AttemptRecord fromJson(const Json& json);
};

// A model test: one scene on one backend combination, and the outcome of
// the attempt it shows.
struct TestRecord : TaskOutcome {
  std::string name;  // <group>.<name>.<suffix>
  std::string group;
  std::string scene;
  std::string sceneFile;
  std::string description;
  std::string backend;  // the combination's suffix
  // The admissible variant's --admissible spelling (SPEC 7); "" for the
  // model's own test (and not written).
  std::string admissible;
  comparison::Verdict verdict = comparison::Verdict::Crash;     // after expected failures and retries
  // The word results.json had for "verdict" where it is no verdict (a newer
  // lightcts's, or a hand edit): `verdict` is then Crash, a failure to every
  // rule, and the reports show this word; "" otherwise.
  std::string unknownVerdict;
  comparison::Verdict rawVerdict = comparison::Verdict::Crash;  // what the shown attempt said
  std::string expectedReason;  // the expected-failures line's reason, "" when not listed
  std::vector<AttemptRecord> attempts;  // a retried test's every attempt; empty (and not written) otherwise

  std::string verdictWord() const;  // unknownVerdict, else the verdict's name
  // The verdict, none for an unknown word; and what it means to CI and to
  // the report, where an unknown word is a failure that needs attention.
  std::optional<comparison::Verdict> knownVerdict() const;
  comparison::CiOutcome ciOutcome() const;
  bool needsAttention() const;
  Json toJson() const;
  static TestRecord fromJson(const Json& json);
};

// A backend's mutation check in three buckets: "other" holds the statuses
// that prove nothing (NotSupported, Crash, Timeout, NotRun).
struct MutantCounts {
  int killed = 0;
  int survived = 0;
  int other = 0;
  bool operator==(const MutantCounts&) const = default;
};

// Every task's stage times summed over a backend, the mutation check's
// included: where its worker time went, references against the rest.
struct TaskTimes {
  long long tasks = 0;  // tasks that reported times
  double referenceMs = 0;
  double totalMs = 0;
  TaskTimes& operator+=(const TaskTimes& other);
};
TaskTimes taskTimesOf(const std::vector<TaskResult>& results);

// What a worker said of its device: the precision it reports, which its
// tolerances use (docs/tolerances.md).
struct DeviceRecord {
  std::string name;
  std::string driver;
  std::string driverVersion;
  std::string apiVersion;
  std::string selectedBy;
  long long subPixelBits = 0;
  long long subTexelBits = 0;

  Json toJson() const;
  static DeviceRecord fromJson(const Json& json);
};

struct BackendRecord {
  std::string backend;  // the combination's suffix
  std::string apiBackend;
  std::string driverOption;
  comparison::BackendStatus status = comparison::BackendStatus::Error;
  std::string message;
  std::optional<DeviceRecord> device;  // none when no worker got its backend up
  std::string expectedFailuresFile;
  std::map<comparison::Verdict, int> counts;  // the model's tests: in report order, zeros only where listedWhenZero
  MutantCounts mutantCounts;
  // The admissible variants' tests (none unless the run asked for some).
  std::map<comparison::Verdict, int> admissibleCounts;
  double wallSeconds = 0;
  TaskTimes taskTimes;
  std::string log;  // relative to the run folder

  Json toJson() const;
  static BackendRecord fromJson(const Json& json);
};

struct MutantRecord {
  std::string mutant;  // the --mutant spelling
  std::string what;
  std::string backend;
  comparison::MutantStatus status = comparison::MutantStatus::Crash;
  std::vector<std::string> killers;   // the scenes meant to catch it
  std::vector<std::string> killedBy;  // the scenes that did, <group>.<name>
  std::optional<EvidenceRecord> evidence;  // its first kill's, with the test

  Json toJson() const;
  static MutantRecord fromJson(const Json& json);
};

// An admissible variant on a backend, over its tests of the run: derived
// from the tests (results::admissibleRecords), for the summary and the reports.
struct AdmissibleRecord {
  std::string variant;  // the --admissible spelling
  std::string what;
  std::string grant;    // the specification's sentence that allows it
  std::string backend;
  comparison::AdmissibleStatus status = comparison::AdmissibleStatus::Incomplete;
  int tests = 0;
  std::vector<std::string> failed;    // tests that are run failures (the unsound evidence)
  std::vector<std::string> expected;  // tests that failed as their expected-failures line says

  Json toJson() const;
  static AdmissibleRecord fromJson(const Json& json);
};

// The machine a run (or shard) ran on.
struct MachineRecord {
  std::string hostname;
  std::string cpu;
  long long cores = 0;
  std::string os;

  Json toJson() const;
  static MachineRecord fromJson(const Json& json);
};

// --include, --exclude and --caselist as given (empty: every test).
struct SelectionRecord {
  std::vector<std::string> include;
  std::vector<std::string> exclude;
  std::vector<std::string> caselists;

  Json toJson() const;
  static SelectionRecord fromJson(const Json& json);
};

// A file that chose or judged the tests, with a digest of its bytes.
struct BaselineFile {
  std::string kind;  // "expected-failures" | "caselist"
  std::string path;
  std::string sha256;

  Json toJson() const;
  static BaselineFile fromJson(const Json& json);
};

// A mutant the run did not check, and why.
struct MutantNotChecked {
  std::string mutant;
  std::string reason;

  Json toJson() const;
  static MutantNotChecked fromJson(const Json& json);
};

// `run --shard I/N`: which shard of which partition.
struct ShardRecord {
  long long index = 0;  // from 1
  long long total = 0;
  std::string partition;   // a digest of the units and each one's shard
  std::string balancedBy;  // "test count" | "timings"
  std::string timingsFile;
  long long testsInRun = 0;
  long long units = 0;
  long long unitsInRun = 0;

  Json toJson() const;
  static ShardRecord fromJson(const Json& json);
};

// The whole of results.json. `shard` is null for a whole run (merged or
// not) and the shard's description in a shard; `mergedFrom` is written only
// by `merge`. "slowest" is not stored: the writer derives it from the tests.
struct RunRecord {
  std::string lightctsRevision;
  std::string startedUtc;
  double durationSeconds = 0;
  std::string command;
  MachineRecord machine;
  std::string scenesDir;
  std::string scenesDigest;
  SelectionRecord selection;
  std::vector<BaselineFile> baselineFiles;
  std::vector<std::string> mutantsRun;
  std::string mutantCheck;  // "killers" | "all-scenes"
  std::vector<MutantNotChecked> mutantsNotChecked;
  std::optional<long long> evidenceLimit;  // none where a shard did not say
  std::string evidenceUrl;
  std::optional<long long> jobs;
  std::optional<ShardRecord> shard;  // none for a whole run
  Json mergedFrom = nullptr;  // merge only: each shard's folder, shard, duration and machine
  std::string referenceCache;  // "fresh" or the cache folder
  std::optional<double> timeoutSeconds;
  std::optional<long long> flakeRetries;
  bool flakesFail = false;
  std::vector<BackendRecord> backends;
  std::vector<TestRecord> tests;
  std::vector<MutantRecord> mutants;
  std::vector<AdmissibleRecord> admissible;
  std::vector<SceneBudgetRecord> budgets;

  bool isShard() const { return shard.has_value(); }
  Json toJson() const;
  // Throws std::invalid_argument when `json` is not a lightcts results.json
  // or a record in it is not an object.
  static RunRecord fromJson(const Json& json);
};

// The ten slowest tests by timings_ms.total, slowest first: results.json's
// "slowest", the run's summary and the report's table.
struct SlowTest {
  std::string name;
  double totalMs = 0;
};
std::vector<SlowTest> slowestTests(const std::vector<TestRecord>& tests);

}  // namespace results
