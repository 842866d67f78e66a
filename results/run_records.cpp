#include "results/run_records.h"

#include <algorithm>
#include <stdexcept>

namespace results {
namespace {

using comparison::Verdict;

// Reading: a key that is missing or of another type reads as its default,
// so a record of a run that broke half way still reads.
std::string text(const Json& json, const char* key) {
  const auto it = json.find(key);
  return it != json.end() && it->is_string() ? it->get<std::string>() : std::string();
}

double number(const Json& json, const char* key) {
  const auto it = json.find(key);
  return it != json.end() && it->is_number() ? it->get<double>() : 0.0;
}

Json carried(const Json& json, const char* key, Json absent = nullptr) {
  const auto it = json.find(key);
  return it != json.end() ? *it : absent;
}

std::vector<std::string> texts(const Json& json, const char* key) {
  std::vector<std::string> items;
  const auto it = json.find(key);
  if (it == json.end() || !it->is_array()) return items;
  for (const Json& item : *it)
    if (item.is_string()) items.push_back(item.get<std::string>());
  return items;
}

Verdict verdictAt(const Json& json, const char* key) {
  return comparison::parseVerdict(text(json, key)).value_or(Verdict::Crash);
}

const Json& objectAt(const Json& array, std::size_t i, const char* what) {
  if (!array[i].is_object()) throw std::invalid_argument(std::string("a record of \"") + what + "\" is not an object");
  return array[i];
}

template <typename Record>
std::vector<Record> recordsAt(const Json& json, const char* key) {
  std::vector<Record> records;
  const auto it = json.find(key);
  if (it == json.end() || !it->is_array()) return records;
  for (std::size_t i = 0; i < it->size(); ++i) records.push_back(Record::fromJson(objectAt(*it, i, key)));
  return records;
}

template <typename Record>
Json arrayOf(const std::vector<Record>& records) {
  Json array = Json::array();
  for (const Record& record : records) array.push_back(record.toJson());
  return array;
}

// The outcome's keys after "message", in results.json's order.
constexpr std::pair<Json TaskOutcome::*, const char*> kOutcomeValues[] = {
    {&TaskOutcome::metrics, "metrics"}, {&TaskOutcome::frames, "frames"}, {&TaskOutcome::poppingScore, "popping_score"}};
constexpr const char* kTimingsKey = "timings_ms";

void writeOutcome(const TaskOutcome& outcome, Json& json) {
  json["message"] = outcome.message;
  for (const auto& [field, key] : kOutcomeValues) json[key] = outcome.*field;
  json[kTimingsKey] = outcome.timingsMs ? outcome.timingsMs->toJson() : Json(nullptr);
  json["evidence"] = outcome.evidence;
}

void readOutcome(const Json& json, TaskOutcome& outcome) {
  outcome.message = text(json, "message");
  for (const auto& [field, key] : kOutcomeValues) outcome.*field = carried(json, key);
  outcome.timingsMs = StageTimes::fromJson(carried(json, kTimingsKey));
  outcome.evidence = carried(json, "evidence");
}

// A test's words before its verdicts, in results.json's order.
constexpr std::pair<std::string TestRecord::*, const char*> kTestWords[] = {
    {&TestRecord::name, "name"},           {&TestRecord::group, "group"},
    {&TestRecord::scene, "scene"},         {&TestRecord::sceneFile, "scene_file"},
    {&TestRecord::description, "description"}, {&TestRecord::backend, "backend"}};

}  // namespace

Json StageTimes::toJson() const {
  Json json = Json::object();
  for (const auto& [field, key] : kFields) json[key] = this->*field;
  return json;
}

std::optional<StageTimes> StageTimes::fromJson(const Json& json) {
  if (!json.is_object()) return std::nullopt;
  StageTimes times;
  for (const auto& [field, key] : kFields) times.*field = number(json, key);
  return times;
}

Json TaskResult::toJson() const {
  Json json = {{"test", test}, {"raw_verdict", comparison::verdictName(rawVerdict)}};
  writeOutcome(*this, json);
  return json;
}

TaskResult TaskResult::fromJson(const Json& json) {
  TaskResult result;
  result.test = text(json, "test");
  result.rawVerdict = verdictAt(json, "raw_verdict");
  readOutcome(json, result);
  return result;
}

TaskResult TaskResult::abnormal(const std::string& test, Verdict verdict, const std::string& message) {
  TaskResult result;
  result.test = test;
  result.rawVerdict = verdict;
  result.message = message;
  return result;
}

Json AttemptRecord::toJson() const {
  return {{"raw_verdict", comparison::verdictName(rawVerdict)}, {"message", message}, {"log", log}};
}

AttemptRecord AttemptRecord::fromJson(const Json& json) {
  return {verdictAt(json, "raw_verdict"), text(json, "message"), text(json, "log")};
}

Json TestRecord::toJson() const {
  Json record = Json::object();
  for (const auto& [field, key] : kTestWords) record[key] = this->*field;
  if (!admissible.empty()) record["admissible"] = admissible;
  record["verdict"] = comparison::verdictName(verdict);
  record["raw_verdict"] = comparison::verdictName(rawVerdict);
  record["expected_reason"] = expectedReason;
  writeOutcome(*this, record);
  if (!attempts.empty()) record["attempts"] = arrayOf(attempts);
  return record;
}

TestRecord TestRecord::fromJson(const Json& json) {
  TestRecord t;
  for (const auto& [field, key] : kTestWords) t.*field = text(json, key);
  t.admissible = text(json, "admissible");
  t.verdict = verdictAt(json, "verdict");
  t.rawVerdict = verdictAt(json, "raw_verdict");
  t.expectedReason = text(json, "expected_reason");
  readOutcome(json, t);
  t.attempts = recordsAt<AttemptRecord>(json, "attempts");
  return t;
}

TaskTimes& TaskTimes::operator+=(const TaskTimes& other) {
  tasks += other.tasks;
  referenceMs += other.referenceMs;
  totalMs += other.totalMs;
  return *this;
}

TaskTimes taskTimesOf(const std::vector<TaskResult>& results) {
  TaskTimes times;
  for (const TaskResult& r : results) {
    if (!r.timingsMs) continue;
    times.referenceMs += r.timingsMs->reference;
    times.totalMs += r.timingsMs->total;
    ++times.tasks;
  }
  return times;
}

namespace {

// Verdict counts in report order; zeros only where listedWhenZero (`all`: every zero left out).
Json countsJson(const std::map<Verdict, int>& counts, bool zeros) {
  Json json = Json::object();
  for (const Verdict verdict : comparison::kAllVerdicts) {
    const auto it = counts.find(verdict);
    const int n = it == counts.end() ? 0 : it->second;
    if (n > 0 || (zeros && comparison::listedWhenZero(verdict))) json[std::string(comparison::verdictName(verdict))] = n;
  }
  return json;
}

std::map<Verdict, int> countsAt(const Json& json, const char* key) {
  std::map<Verdict, int> counts;
  if (const auto it = json.find(key); it != json.end() && it->is_object())
    for (const auto& [word, n] : it->items())
      if (const auto verdict = comparison::parseVerdict(word); verdict && n.is_number_integer())
        counts[*verdict] = n.get<int>();
  return counts;
}

}  // namespace

Json BackendRecord::toJson() const {
  Json record = {{"backend", backend},
          {"api_backend", apiBackend},
          {"driver_option", driverOption},
          {"status", comparison::backendStatusName(status)},
          {"message", message},
          {"device", device},
          {"expected_failures_file", expectedFailuresFile},
          {"counts", countsJson(counts, true)},
          {"mutant_counts",
           {{"killed", mutantCounts.killed}, {"survived", mutantCounts.survived}, {"other", mutantCounts.other}}}};
  if (!admissibleCounts.empty()) record["admissible_counts"] = countsJson(admissibleCounts, false);
  record["wall_s"] = wallSeconds;
  record["task_ms"] = {{"tasks", taskTimes.tasks}, {"reference", taskTimes.referenceMs}, {"total", taskTimes.totalMs}};
  record["log"] = log;
  return record;
}

BackendRecord BackendRecord::fromJson(const Json& json) {
  BackendRecord b;
  b.backend = text(json, "backend");
  b.apiBackend = text(json, "api_backend");
  b.driverOption = text(json, "driver_option");
  b.status = comparison::parseBackendStatus(text(json, "status")).value_or(comparison::BackendStatus::Error);
  b.message = text(json, "message");
  b.device = carried(json, "device");
  b.expectedFailuresFile = text(json, "expected_failures_file");
  b.counts = countsAt(json, "counts");
  b.admissibleCounts = countsAt(json, "admissible_counts");
  const Json mutantCounts = carried(json, "mutant_counts", Json::object());
  if (mutantCounts.is_object())
    b.mutantCounts = {int(number(mutantCounts, "killed")), int(number(mutantCounts, "survived")),
                      int(number(mutantCounts, "other"))};
  b.wallSeconds = number(json, "wall_s");
  const Json taskMs = carried(json, "task_ms", Json::object());
  if (taskMs.is_object())
    b.taskTimes = {(long long)number(taskMs, "tasks"), number(taskMs, "reference"), number(taskMs, "total")};
  b.log = text(json, "log");
  return b;
}

Json MutantRecord::toJson() const {
  return {{"mutant", mutant},
          {"what", what},
          {"backend", backend},
          {"status", comparison::mutantStatusName(status)},
          {"killers", killers},
          {"killed_by", killedBy},
          {"evidence", evidence}};
}

MutantRecord MutantRecord::fromJson(const Json& json) {
  return {text(json, "mutant"),
          text(json, "what"),
          text(json, "backend"),
          comparison::parseMutantStatus(text(json, "status")).value_or(comparison::MutantStatus::Crash),
          texts(json, "killers"),
          texts(json, "killed_by"),
          carried(json, "evidence")};
}

Json AdmissibleRecord::toJson() const {
  return {{"variant", variant},   {"what", what},     {"grant", grant},   {"backend", backend},
          {"status", comparison::admissibleStatusName(status)}, {"tests", tests}, {"failed", failed},
          {"expected", expected}};
}

AdmissibleRecord AdmissibleRecord::fromJson(const Json& json) {
  return {text(json, "variant"),
          text(json, "what"),
          text(json, "grant"),
          text(json, "backend"),
          comparison::parseAdmissibleStatus(text(json, "status")).value_or(comparison::AdmissibleStatus::Incomplete),
          int(number(json, "tests")),
          texts(json, "failed"),
          texts(json, "expected")};
}

Json slowestTests(const std::vector<TestRecord>& tests) {
  std::vector<std::pair<double, std::string>> times;
  for (const TestRecord& t : tests)
    if (t.timingsMs) times.emplace_back(t.timingsMs->total, t.name);
  std::sort(times.begin(), times.end(), std::greater<>());
  if (times.size() > 10) times.resize(10);
  Json slowest = Json::array();
  for (const auto& [ms, name] : times) slowest.push_back({{"name", name}, {"total_ms", ms}});
  return slowest;
}

Json RunRecord::toJson() const {
  Json run = {{"format", "lightcts-results"},
              {"version", 1},
              {"lightcts_revision", lightctsRevision},
              {"started_utc", startedUtc},
              {"duration_s", durationSeconds},
              {"command", command},
              {"machine", machine},
              {"scenes_dir", scenesDir},
              {"scenes_digest", scenesDigest},
              {"selection", selection},
              {"baseline_files", baselineFiles},
              {"mutants_run", mutantsRun},
              {"mutant_check", mutantCheck},
              {"mutants_not_checked", mutantsNotChecked},
              {"evidence_limit", evidenceLimit},
              {"evidence_url", evidenceUrl},
              {"jobs", jobs},
              {"shard", shard}};
  if (!mergedFrom.is_null()) run["merged_from"] = mergedFrom;
  run["reference_cache"] = referenceCache;
  run["timeout_s"] = timeoutSeconds;
  run["flake_retries"] = flakeRetries;
  run["flakes_fail"] = flakesFail;
  run["backends"] = arrayOf(backends);
  run["tests"] = arrayOf(tests);
  run["mutants"] = arrayOf(mutants);
  run["admissible"] = arrayOf(admissible);
  run["budgets"] = budgets;
  run["slowest"] = slowestTests(tests);
  return run;
}

namespace {

// What a run says of itself: its words and the values it carries through.
constexpr std::pair<std::string RunRecord::*, const char*> kRunWords[] = {
    {&RunRecord::lightctsRevision, "lightcts_revision"}, {&RunRecord::startedUtc, "started_utc"},
    {&RunRecord::command, "command"},                    {&RunRecord::scenesDir, "scenes_dir"},
    {&RunRecord::scenesDigest, "scenes_digest"},         {&RunRecord::mutantCheck, "mutant_check"},
    {&RunRecord::evidenceUrl, "evidence_url"}};
constexpr std::pair<Json RunRecord::*, const char*> kRunValues[] = {
    {&RunRecord::machine, "machine"},          {&RunRecord::selection, "selection"},
    {&RunRecord::evidenceLimit, "evidence_limit"}, {&RunRecord::jobs, "jobs"},
    {&RunRecord::shard, "shard"},              {&RunRecord::mergedFrom, "merged_from"},
    {&RunRecord::referenceCache, "reference_cache"}, {&RunRecord::timeoutSeconds, "timeout_s"},
    {&RunRecord::flakeRetries, "flake_retries"}};

}  // namespace

RunRecord RunRecord::fromJson(const Json& json) {
  if (!json.is_object() || text(json, "format") != "lightcts-results")
    throw std::invalid_argument("not a lightcts results.json");
  RunRecord r;
  for (const auto& [field, key] : kRunWords) r.*field = text(json, key);
  for (const auto& [field, key] : kRunValues) r.*field = carried(json, key);
  r.durationSeconds = number(json, "duration_s");
  r.baselineFiles = carried(json, "baseline_files", Json::array());
  r.mutantsRun = texts(json, "mutants_run");
  r.mutantsNotChecked = carried(json, "mutants_not_checked", Json::array());
  const Json flakesFail = carried(json, "flakes_fail", false);
  r.flakesFail = flakesFail.is_boolean() && flakesFail.get<bool>();
  r.backends = recordsAt<BackendRecord>(json, "backends");
  r.tests = recordsAt<TestRecord>(json, "tests");
  r.mutants = recordsAt<MutantRecord>(json, "mutants");
  r.admissible = recordsAt<AdmissibleRecord>(json, "admissible");
  r.budgets = carried(json, "budgets", Json::object());
  return r;
}

}  // namespace results
