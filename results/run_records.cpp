#include "results/run_records.h"

#include "results/json_fields.h"

#include <algorithm>
#include <stdexcept>

namespace results {
namespace {

using namespace fields;
using comparison::Verdict;

// A verdict word no verdict has (a newer lightcts's, or a hand edit) reads as
// a Crash, a failure and never a pass, and the record says which word it was.
Verdict verdictAt(const Json& json, const char* key, std::string* unknownWord = nullptr) {
  const std::string word = text(json, key);
  const std::optional<Verdict> verdict = comparison::parseVerdict(word);
  if (!verdict && unknownWord) *unknownWord = word.empty() ? "unknown" : word;
  return verdict.value_or(Verdict::Crash);
}

const Json& objectAt(const Json& array, std::size_t i, const char* what) {
  if (!array[i].is_object())
    throw std::invalid_argument(std::string(what) + "[" + std::to_string(i) + "] is not an object");
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

std::optional<long long> optionalInteger(const Json& json, const char* key) {
  const auto it = json.find(key);
  return it != json.end() && it->is_number() ? std::optional<long long>(it->get<long long>()) : std::nullopt;
}

template <typename T>
Json optionalJson(const std::optional<T>& value) {
  return value ? Json(*value) : Json(nullptr);
}

// A test's words before its verdicts, in results.json's order.
constexpr std::pair<std::string TestRecord::*, const char*> kTestWords[] = {
    {&TestRecord::name, "name"},           {&TestRecord::group, "group"},
    {&TestRecord::scene, "scene"},         {&TestRecord::sceneFile, "scene_file"},
    {&TestRecord::description, "description"}, {&TestRecord::backend, "backend"}};

}  // namespace

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
  record["verdict"] = verdictWord();
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
  t.verdict = verdictAt(json, "verdict", &t.unknownVerdict);
  t.rawVerdict = verdictAt(json, "raw_verdict");
  t.expectedReason = text(json, "expected_reason");
  readOutcome(json, t);
  t.attempts = recordsAt<AttemptRecord>(json, "attempts");
  return t;
}

std::string TestRecord::verdictWord() const {
  return unknownVerdict.empty() ? std::string(comparison::verdictName(verdict)) : unknownVerdict;
}

std::optional<Verdict> TestRecord::knownVerdict() const {
  return unknownVerdict.empty() ? std::optional<Verdict>(verdict) : std::nullopt;
}

comparison::CiOutcome TestRecord::ciOutcome() const {
  return unknownVerdict.empty() ? comparison::ciOutcome(verdict) : comparison::CiOutcome::Failure;
}

bool TestRecord::needsAttention() const { return !unknownVerdict.empty() || comparison::needsAttention(verdict); }

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

Json DeviceRecord::toJson() const {
  return {{"name", name},
          {"driver", driver},
          {"driver_version", driverVersion},
          {"api_version", apiVersion},
          {"selected_by", selectedBy},
          {"sub_pixel_bits", subPixelBits},
          {"sub_texel_bits", subTexelBits}};
}

DeviceRecord DeviceRecord::fromJson(const Json& json) {
  return {text(json, "name"),          text(json, "driver"),
          text(json, "driver_version"), text(json, "api_version"),
          text(json, "selected_by"),    integer(json, "sub_pixel_bits"),
          integer(json, "sub_texel_bits")};
}

Json BackendRecord::toJson() const {
  Json record = {{"backend", backend},
          {"api_backend", apiBackend},
          {"driver_option", driverOption},
          {"status", comparison::backendStatusName(status)},
          {"message", message},
          {"device", device ? device->toJson() : Json(nullptr)},
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
  if (const Json device = carried(json, "device"); device.is_object()) b.device = DeviceRecord::fromJson(device);
  b.expectedFailuresFile = text(json, "expected_failures_file");
  b.counts = countsAt(json, "counts");
  b.admissibleCounts = countsAt(json, "admissible_counts");
  if (const Json mutantCounts = carried(json, "mutant_counts"); mutantCounts.is_object())
    b.mutantCounts = {int(integer(mutantCounts, "killed")), int(integer(mutantCounts, "survived")),
                      int(integer(mutantCounts, "other"))};
  b.wallSeconds = number(json, "wall_s");
  if (const Json taskMs = carried(json, "task_ms"); taskMs.is_object())
    b.taskTimes = {integer(taskMs, "tasks"), number(taskMs, "reference"), number(taskMs, "total")};
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
          {"evidence", evidence ? evidence->toJson() : Json(nullptr)}};
}

MutantRecord MutantRecord::fromJson(const Json& json) {
  MutantRecord m{text(json, "mutant"),
                 text(json, "what"),
                 text(json, "backend"),
                 comparison::parseMutantStatus(text(json, "status")).value_or(comparison::MutantStatus::Crash),
                 texts(json, "killers"),
                 texts(json, "killed_by"),
                 std::nullopt};
  if (const Json evidence = carried(json, "evidence"); evidence.is_object())
    m.evidence = EvidenceRecord::fromJson(evidence);
  return m;
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
          int(integer(json, "tests")),
          texts(json, "failed"),
          texts(json, "expected")};
}

Json MachineRecord::toJson() const { return {{"hostname", hostname}, {"cpu", cpu}, {"cores", cores}, {"os", os}}; }

MachineRecord MachineRecord::fromJson(const Json& json) {
  return {text(json, "hostname"), text(json, "cpu"), integer(json, "cores"), text(json, "os")};
}

Json SelectionRecord::toJson() const { return {{"include", include}, {"exclude", exclude}, {"caselists", caselists}}; }

SelectionRecord SelectionRecord::fromJson(const Json& json) {
  return {texts(json, "include"), texts(json, "exclude"), texts(json, "caselists")};
}

Json BaselineFile::toJson() const { return {{"kind", kind}, {"path", path}, {"sha256", sha256}}; }

BaselineFile BaselineFile::fromJson(const Json& json) {
  return {text(json, "kind"), text(json, "path"), text(json, "sha256")};
}

Json MutantNotChecked::toJson() const { return {{"mutant", mutant}, {"reason", reason}}; }

MutantNotChecked MutantNotChecked::fromJson(const Json& json) { return {text(json, "mutant"), text(json, "reason")}; }

Json ShardRecord::toJson() const {
  return {{"index", index},
          {"total", total},
          {"partition", partition},
          {"balanced_by", balancedBy},
          {"timings_file", timingsFile},
          {"tests_in_run", testsInRun},
          {"units", units},
          {"units_in_run", unitsInRun}};
}

ShardRecord ShardRecord::fromJson(const Json& json) {
  return {integer(json, "index"),       integer(json, "total"),        text(json, "partition"),
          text(json, "balanced_by"),    text(json, "timings_file"),    integer(json, "tests_in_run"),
          integer(json, "units"),       integer(json, "units_in_run")};
}

std::vector<SlowTest> slowestTests(const std::vector<TestRecord>& tests) {
  std::vector<SlowTest> times;
  for (const TestRecord& t : tests)
    if (t.timingsMs) times.push_back({t.name, t.timingsMs->total});
  std::stable_sort(times.begin(), times.end(), [](const SlowTest& a, const SlowTest& b) {
    return a.totalMs != b.totalMs ? a.totalMs > b.totalMs : a.name > b.name;
  });
  if (times.size() > 10) times.resize(10);
  return times;
}

Json RunRecord::toJson() const {
  Json run = {{"format", "lightcts-results"},
              {"version", 1},
              {"lightcts_revision", lightctsRevision},
              {"started_utc", startedUtc},
              {"duration_s", durationSeconds},
              {"command", command},
              {"machine", machine.toJson()},
              {"scenes_dir", scenesDir},
              {"scenes_digest", scenesDigest},
              {"selection", selection.toJson()},
              {"baseline_files", arrayOf(baselineFiles)},
              {"mutants_run", mutantsRun},
              {"mutant_check", mutantCheck},
              {"mutants_not_checked", arrayOf(mutantsNotChecked)},
              {"evidence_limit", optionalJson(evidenceLimit)},
              {"evidence_url", evidenceUrl},
              {"jobs", optionalJson(jobs)},
              {"shard", shard ? shard->toJson() : Json(nullptr)}};
  if (!mergedFrom.is_null()) run["merged_from"] = mergedFrom;
  run["reference_cache"] = referenceCache;
  run["timeout_s"] = optionalJson(timeoutSeconds);
  run["flake_retries"] = optionalJson(flakeRetries);
  run["flakes_fail"] = flakesFail;
  run["backends"] = arrayOf(backends);
  run["tests"] = arrayOf(tests);
  run["mutants"] = arrayOf(mutants);
  run["admissible"] = arrayOf(admissible);
  run["budgets"] = budgetsJson(budgets);
  Json slowest = Json::array();
  for (const SlowTest& s : slowestTests(tests)) slowest.push_back({{"name", s.name}, {"total_ms", s.totalMs}});
  run["slowest"] = slowest;
  return run;
}

namespace {

// What a run says of itself in words.
constexpr std::pair<std::string RunRecord::*, const char*> kRunWords[] = {
    {&RunRecord::lightctsRevision, "lightcts_revision"}, {&RunRecord::startedUtc, "started_utc"},
    {&RunRecord::command, "command"},                    {&RunRecord::scenesDir, "scenes_dir"},
    {&RunRecord::scenesDigest, "scenes_digest"},         {&RunRecord::mutantCheck, "mutant_check"},
    {&RunRecord::evidenceUrl, "evidence_url"},           {&RunRecord::referenceCache, "reference_cache"}};

}  // namespace

RunRecord RunRecord::fromJson(const Json& json) {
  if (!json.is_object() || text(json, "format") != "lightcts-results")
    throw std::invalid_argument("not a lightcts results.json");
  RunRecord r;
  for (const auto& [field, key] : kRunWords) r.*field = text(json, key);
  r.durationSeconds = number(json, "duration_s");
  if (const Json machine = carried(json, "machine"); machine.is_object()) r.machine = MachineRecord::fromJson(machine);
  if (const Json selection = carried(json, "selection"); selection.is_object())
    r.selection = SelectionRecord::fromJson(selection);
  r.baselineFiles = objects<BaselineFile>(json, "baseline_files", BaselineFile::fromJson);
  r.mutantsRun = texts(json, "mutants_run");
  r.mutantsNotChecked = objects<MutantNotChecked>(json, "mutants_not_checked", MutantNotChecked::fromJson);
  r.evidenceLimit = optionalInteger(json, "evidence_limit");
  r.jobs = optionalInteger(json, "jobs");
  if (const Json shard = carried(json, "shard"); shard.is_object()) r.shard = ShardRecord::fromJson(shard);
  r.mergedFrom = carried(json, "merged_from");
  r.timeoutSeconds = measured(json, "timeout_s");
  r.flakeRetries = optionalInteger(json, "flake_retries");
  r.flakesFail = boolean(json, "flakes_fail");
  r.backends = recordsAt<BackendRecord>(json, "backends");
  r.tests = recordsAt<TestRecord>(json, "tests");
  r.mutants = recordsAt<MutantRecord>(json, "mutants");
  r.admissible = recordsAt<AdmissibleRecord>(json, "admissible");
  r.budgets = budgetsFromJson(carried(json, "budgets", Json::object()));
  return r;
}

}  // namespace results
