// results.json's records (docs/results-format.md), typed: a worker's result
// for one task, a test, a backend, a mutant on a backend and the run around
// them, each with one reader and one writer. `lightcts run` assembles them
// from its workers' results; `lightcts merge` reads them back from each
// shard and joins them; both write through the same writers, so a merged
// run has the keys of one run in the same order. What a record only carries
// through (a test's metrics, frames and evidence, a device's description,
// the machine) stays JSON: the worker and the comparison own its shape.
#pragma once

#include "comparison/run_status.h"
#include "comparison/verdict.h"

#include <nlohmann/json.hpp>

#include <array>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace results {

using Json = nlohmann::ordered_json;

// Where a task's time went, in milliseconds (results.json "timings_ms"): the
// worker's stages, then their total.
struct StageTimes {
  double reference = 0;
  double pipeline = 0;
  double draw = 0;
  double readback = 0;
  double compare = 0;
  double total = 0;

  // Every field with its key, in results.json's order: the one spelling of
  // the stage names, which the writer, the reader and the reports' table use.
  static constexpr std::array<std::pair<double StageTimes::*, const char*>, 6> kFields = {{
      {&StageTimes::reference, "reference"},
      {&StageTimes::pipeline, "pipeline"},
      {&StageTimes::draw, "draw"},
      {&StageTimes::readback, "readback"},
      {&StageTimes::compare, "compare"},
      {&StageTimes::total, "total"},
  }};
  Json toJson() const;
  // null (a task that never reported times) or anything but an object:
  // nullopt; a stage that is missing or no number reads as 0.
  static std::optional<StageTimes> fromJson(const Json& json);
};

// What a task's comparison came to, as a worker reports it and as a test's
// record keeps it.
struct TaskOutcome {
  std::string message;
  Json metrics = nullptr;
  Json frames = nullptr;
  Json poppingScore = nullptr;
  std::optional<StageTimes> timingsMs;  // none for a Crash, Timeout, NotSupported or NotRun
  Json evidence = nullptr;
};

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
  comparison::Verdict rawVerdict = comparison::Verdict::Crash;  // what the shown attempt said
  std::string expectedReason;  // the expected-failures line's reason, "" when not listed
  std::vector<AttemptRecord> attempts;  // a retried test's every attempt; empty (and not written) otherwise

  Json toJson() const;
  static TestRecord fromJson(const Json& json);
};

// A backend's mutation check in three buckets: "other" holds the statuses
// that prove nothing (NotSupported, Crash, Timeout).
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

struct BackendRecord {
  std::string backend;  // the combination's suffix
  std::string apiBackend;
  std::string driverOption;
  comparison::BackendStatus status = comparison::BackendStatus::Error;
  std::string message;
  Json device = nullptr;  // what the worker said of its device, or null
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
  Json evidence = nullptr;            // its first kill's, with "test"

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

// The whole of results.json. `shard` is null for a whole run (merged or
// not) and the shard's description in a shard; `mergedFrom` is written only
// by `merge`. "slowest" is not stored: the writer derives it from the tests.
struct RunRecord {
  std::string lightctsRevision;
  std::string startedUtc;
  double durationSeconds = 0;
  std::string command;
  Json machine = nullptr;
  std::string scenesDir;
  std::string scenesDigest;
  Json selection = nullptr;
  Json baselineFiles = Json::array();
  std::vector<std::string> mutantsRun;
  std::string mutantCheck;  // "killers" | "all-scenes"
  Json mutantsNotChecked = Json::array();
  Json evidenceLimit = nullptr;  // an integer, or null where a shard did not say
  std::string evidenceUrl;
  Json jobs = nullptr;
  Json shard = nullptr;
  Json mergedFrom = nullptr;  // merge only: each shard's folder, shard, duration and machine
  Json referenceCache = nullptr;  // "fresh" or the cache folder
  Json timeoutSeconds = nullptr;
  Json flakeRetries = nullptr;
  bool flakesFail = false;
  std::vector<BackendRecord> backends;
  std::vector<TestRecord> tests;
  std::vector<MutantRecord> mutants;
  std::vector<AdmissibleRecord> admissible;
  Json budgets = Json::object();

  bool isShard() const { return shard.is_object(); }
  Json toJson() const;
  // Throws std::invalid_argument when `json` is not a lightcts results.json
  // or a record in it is not an object.
  static RunRecord fromJson(const Json& json);
};

// The ten slowest tests by timings_ms.total, for results.json's "slowest".
Json slowestTests(const std::vector<TestRecord>& tests);

}  // namespace results
