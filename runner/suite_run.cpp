#include "runner/suite_run.h"

#include "comparison/run_status.h"
#include "comparison/verdict.h"
#include "conformance/scene_catalogue.h"
#include "lighting/scene_loader.h"
#include "reports/csv_writer.h"
#include "reports/html_report.h"
#include "reports/junit_writer.h"
#include "runner/expected_failures.h"
#include "runner/run_metadata.h"
#include "imaging/atomic_file.h"
#include "runner/worker_plan.h"
#include "runner/worker_process.h"
#include "shaders/shader_variant.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <ostream>
#include <sstream>
#include <stdexcept>

namespace runner {
namespace {

using Json = nlohmann::ordered_json;
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
using comparison::BackendStatus;
using comparison::MutantStatus;
using comparison::Verdict;

struct CatalogueEntry {
  conformance::SceneFile file;
  std::string description;
};

// Every scene is loaded before any worker starts: a scene with a typo stops
// the run with exit 2 and the JSON path, before anything is written.
std::vector<CatalogueEntry> loadCatalogue(const std::string& scenesDir) {
  std::vector<CatalogueEntry> catalogue;
  for (const conformance::SceneFile& file : conformance::findSceneFiles(scenesDir))
    catalogue.push_back({file, lighting::loadSceneFile(file.path.string()).description});
  return catalogue;
}

std::vector<std::string> mutantsToRun(const RunOptions& options) {
  if (options.noMutants) return {};
  if (!options.mutants.empty()) {
    for (const std::string& m : options.mutants)
      if (!shaders::mutantFromName(m) || m == "none") throw std::invalid_argument("unknown --mutant '" + m + "'");
    return options.mutants;
  }
  std::vector<std::string> all;
  for (const shaders::MutantName& m : shaders::mutantNames()) all.emplace_back(m.name);
  return all;
}

std::string lastLines(const fs::path& file, int count) {
  std::ifstream in(file);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  std::string text;
  for (std::size_t i = lines.size() > std::size_t(count) ? lines.size() - count : 0; i < lines.size(); ++i)
    text += lines[i] + "\n";
  return text;
}

// What one combination's workers said: the device, and a result per task.
struct CombinationOutcome {
  BackendStatus status = BackendStatus::Ran;
  std::string message;
  Json device = nullptr;
  std::vector<Json> results;  // one per task, in plan order
  double wallSeconds = 0;
};

Json abnormalResult(const WorkerTask& task, Verdict verdict, const std::string& message) {
  return {{"test", task.test},       {"raw_verdict", comparison::verdictName(verdict)},
          {"message", message},      {"metrics", nullptr},
          {"frames", Json::array()}, {"popping_score", nullptr},
          {"timings_ms", nullptr},   {"evidence", nullptr}};
}

// Runs the plan in as many workers as it takes: a worker that dies or hangs
// costs its current test (Crash or Timeout) and a new worker picks up at the
// next one. The plan and the workers' stderr go to logs/<fileStem>.plan.json
// and logs/<fileStem>.log (the suffix; <suffix>.retry-N for a retry).
CombinationOutcome runCombination(const WorkerPlan& plan, const RunOptions& options, const fs::path& logsDir,
                                  const std::string& fileStem, std::ostream& out) {
  CombinationOutcome outcome;
  const auto start = Clock::now();
  const fs::path planFile = logsDir / (fileStem + ".plan.json");
  imaging::writeFileAtomically(planFile, planToJson(plan).dump(1) + "\n");
  const fs::path logFile = logsDir / (fileStem + ".log");
  fs::remove(logFile);  // the workers append; an earlier run's lines are not this run's
  const auto timeout = std::chrono::milliseconds(static_cast<long long>(options.timeoutSeconds * 1000));

  std::size_t next = 0;
  while (next < plan.tasks.size()) {
    WorkerProcess worker({options.workerExecutable, "worker", "--plan", planFile.string(), "--start",
                          std::to_string(next)},
                         logFile.string());
    std::string line;
    bool stop = false;
    bool gotResult = false;  // this worker reported at least one test
    bool backendUp = false;  // this worker said "device": its backend was created
    for (;;) {
      const auto status = worker.readLine(timeout, line);
      // A worker that dies or hangs before its backend is up would do the
      // same for every task: the backend is an error, and the run moves on.
      if (status != WorkerProcess::ReadStatus::Line && !backendUp) {
        const bool hung = status == WorkerProcess::ReadStatus::TimedOut;
        const std::string how = worker.finish(hung);
        outcome.status = BackendStatus::Error;
        outcome.message = std::string(hung ? "the backend did not start within the timeout" : "the worker ended") +
                          " before its backend was up (" + how + "); its last output:\n" + lastLines(logFile, 8);
        for (; next < plan.tasks.size(); ++next)
          outcome.results.push_back(
              abnormalResult(plan.tasks[next], hung ? Verdict::Timeout : Verdict::Crash, outcome.message));
        break;
      }
      if (status == WorkerProcess::ReadStatus::TimedOut) {
        const std::string how = worker.finish(true);
        const WorkerTask& task = plan.tasks[next];
        outcome.results.push_back(abnormalResult(task, Verdict::Timeout,
                                                 "no result within " + std::to_string(options.timeoutSeconds) +
                                                     " s; worker " + how));
        out << "  " << Verdict::Timeout << " " << task.test << "\n";
        ++next;
        break;
      }
      if (status == WorkerProcess::ReadStatus::Closed) {
        const std::string how = worker.finish(false);
        // Status 4 after a test's result: the worker reported a driver error
        // and quit, so that a new one starts on a fresh device. No test is lost.
        if (worker.exitStatus() == 4 && gotResult) break;
        if (next < plan.tasks.size()) {
          const WorkerTask& task = plan.tasks[next];
          outcome.results.push_back(abnormalResult(
              task, Verdict::Crash, "the worker ended during this test (" + how + "); its last output:\n" +
                                        lastLines(logFile, 8)));
          out << "  " << Verdict::Crash << " " << task.test << " (" << how << ")\n";
          ++next;
        }
        break;
      }
      Json event;
      try {
        event = Json::parse(line);
      } catch (const Json::parse_error&) {
        continue;  // a driver that prints on stdout; the protocol lines are JSON
      }
      const std::string kind = event.value("kind", "");
      if (kind == "device") {
        outcome.device = event["device"];
        backendUp = true;
      } else if (kind == "backend_unavailable" || kind == "backend_error") {
        // A backend that ran before and is gone now is an error, not a skip.
        const bool skip = kind == "backend_unavailable" && outcome.device.is_null();
        outcome.status = skip ? BackendStatus::NotSupported : BackendStatus::Error;
        outcome.message = event.value("message", "");
        const Verdict verdict = skip ? Verdict::NotSupported : Verdict::Crash;
        for (; next < plan.tasks.size(); ++next)
          outcome.results.push_back(abnormalResult(plan.tasks[next], verdict, outcome.message));
        stop = true;
        break;
      } else if (kind == "result" && event.value("index", -1) == int(next)) {
        event.erase("kind");
        event.erase("index");
        outcome.results.push_back(std::move(event));
        ++next;
        gotResult = true;
      }
    }
    if (stop) break;
  }
  outcome.wallSeconds = std::chrono::duration<double>(Clock::now() - start).count();
  return outcome;
}

// A worker's raw verdict. Workers write only verdictName's words; a result
// without one (or with any other) is from a worker that broke: a Crash.
Verdict rawVerdictOf(const Json& result) {
  return comparison::parseVerdict(result.value("raw_verdict", "")).value_or(Verdict::Crash);
}

Json testRecord(const CatalogueEntry& scene, const std::string& suffix, Json result,
                const ExpectedFailure* listed, Verdict verdict) {
  const std::string raw = result.value("raw_verdict", std::string(comparison::verdictName(Verdict::Crash)));
  Json record = {{"name", result["test"]},
                 {"group", scene.file.group},
                 {"scene", scene.file.name},
                 {"scene_file", scene.file.path.string()},
                 {"description", scene.description},
                 {"backend", suffix},
                 {"verdict", comparison::verdictName(verdict)},
                 {"raw_verdict", raw},
                 {"expected_reason", listed ? listed->reason : ""},
                 {"message", result.value("message", "")}};
  for (const char* key : {"metrics", "frames", "popping_score", "timings_ms", "evidence"})
    record[key] = result.contains(key) ? result[key] : Json(nullptr);
  return record;
}

// Flake detection (docs/results-format.md): an attempt that failed, crashed
// or timed out, and not as the test's expected-failures line says (a known
// failure is not retried), is worth another in a fresh worker. An attempt
// that passes, QualityWarning included, ends the retries.
bool isFailingAttempt(Verdict raw) { return raw == Verdict::Fail || raw == Verdict::Crash || raw == Verdict::Timeout; }

bool worthRetrying(Verdict raw, const ExpectedFailure* listed) {
  return isFailingAttempt(raw) && comparison::isRunFailure(applyExpectation(raw, listed));
}

bool passed(Verdict raw) { return raw == Verdict::Pass || raw == Verdict::QualityWarning; }

// One attempt at a task: the worker's result, and the log of that worker.
struct Attempt {
  Json result;
  std::string log;  // relative to --out: logs/<suffix>.log, logs/<suffix>.retry-N.log
};

struct MutantOutcome {
  MutantStatus status;
  Json record;
};

// A mutant is killed on a backend when at least one scene fails with it that
// passes without it (`cleanVerdicts`: the model's raw verdict per test; with
// --mutants-only it is empty and every failing scene counts).
MutantOutcome mutantRecord(const std::string& mutant, const std::string& suffix, BackendStatus backendStatus,
                           const std::vector<Json>& results, const std::map<std::string, Verdict>& cleanVerdicts) {
  Json killedBy = Json::array();
  Json evidence = nullptr;
  bool crashed = false, timedOut = false;
  for (const Json& r : results) {
    const Verdict raw = rawVerdictOf(r);
    const std::string test = r.value("test", "");
    const auto clean = cleanVerdicts.find(test);
    if (raw == Verdict::Fail && (clean == cleanVerdicts.end() || clean->second == Verdict::Pass)) {
      killedBy.push_back(test.substr(0, test.rfind('.')));
      if (evidence.is_null() && !r["evidence"].is_null()) {
        evidence = r["evidence"];
        evidence["test"] = test;
      }
    }
    crashed = crashed || raw == Verdict::Crash;
    timedOut = timedOut || raw == Verdict::Timeout;
  }
  const MutantStatus status = !killedBy.empty()                            ? MutantStatus::Killed
                              : backendStatus == BackendStatus::NotSupported ? MutantStatus::NotSupported
                              : crashed                                      ? MutantStatus::Crash
                              : timedOut                                     ? MutantStatus::Timeout
                                                                             : MutantStatus::Survived;
  std::string what;
  for (const shaders::MutantName& m : shaders::mutantNames())
    if (m.name == mutant) what = m.what;
  return {status, {{"mutant", mutant},
                   {"what", what},
                   {"backend", suffix},
                   {"status", comparison::mutantStatusName(status)},
                   {"killed_by", killedBy},
                   {"evidence", evidence}}};
}

// results.json's "counts" of one backend, in report order.
Json countsJson(const std::map<Verdict, int>& counted) {
  Json counts = Json::object();
  for (const Verdict verdict : comparison::kAllVerdicts) {
    const auto it = counted.find(verdict);
    const int n = it == counted.end() ? 0 : it->second;
    if (n > 0 || comparison::listedWhenZero(verdict)) counts[std::string(comparison::verdictName(verdict))] = n;
  }
  return counts;
}

std::string joined(const std::vector<std::string>& items) {
  std::string text;
  for (const std::string& item : items) text += (text.empty() ? "" : ", ") + item;
  return text;
}

std::string formatMs(double ms) {
  std::ostringstream text;
  text << std::fixed << std::setprecision(ms < 10 ? 2 : 0) << ms << " ms";
  return text.str();
}

}  // namespace

int runSuite(const RunOptions& options, std::ostream& out, std::ostream& err) {
  const auto started = Clock::now();
  const std::string startedUtc = utcTimestamp();
  // Everything the options name is checked before anything is written.
  std::vector<CatalogueEntry> catalogue;
  ExpectedFailures expected;
  try {
    catalogue = loadCatalogue(options.scenesDir);
    for (const std::string& file : options.expectedFailureFiles) expected.load(file);
  } catch (const std::runtime_error& e) {
    throw std::invalid_argument(e.what());  // a bad scene or baseline is bad input (exit 2)
  }
  const std::vector<BackendCombination> combinations = selectCombinations(options.backends);
  const std::vector<std::string> mutants = mutantsToRun(options);
  if (options.timeoutSeconds <= 0) throw std::invalid_argument("--timeout must be positive");
  if (options.flakeRetries < 0) throw std::invalid_argument("--flake-retries must be 0 or more");
  if (options.mutantsOnly && mutants.empty())
    throw std::invalid_argument("nothing to run: --mutants-only with --no-mutants");

  const fs::path outDir(options.outDir);
  const fs::path logsDir = outDir / "logs";
  fs::create_directories(logsDir);
  // Evidence of an earlier run in the same folder would be mistaken for this one's.
  for (const char* stale : {"evidence", "mutants", "report"}) fs::remove_all(outDir / stale);
  for (const char* stale : {"results.json", "junit.xml", "results.csv", "failures.csv"}) fs::remove(outDir / stale);
  std::vector<fs::path> staleRetryLogs;  // logs/<suffix>.retry-N.*, which this run may not write
  for (const fs::directory_entry& entry : fs::directory_iterator(logsDir))
    if (entry.path().filename().string().find(".retry-") != std::string::npos) staleRetryLogs.push_back(entry.path());
  for (const fs::path& stale : staleRetryLogs) fs::remove(stale);

  Json backendsJson = Json::array();
  Json tests = Json::array();
  Json mutantsJson = Json::array();
  bool anyRan = false, allGood = true;
  std::vector<std::string> flakes;  // "test: Crash, Pass", for the summary
  std::map<std::string, const CatalogueEntry*> sceneOfCase;
  for (const CatalogueEntry& scene : catalogue) sceneOfCase[scene.file.caseName()] = &scene;

  for (const BackendCombination& combination : combinations) {
    WorkerPlan plan{combination, options.device, options.expectDriver, fs::absolute(outDir).string(), {}};
    if (!options.mutantsOnly)
      for (const CatalogueEntry& scene : catalogue)
        plan.tasks.push_back({scene.file.caseName() + "." + combination.suffix, scene.file.path.string(), "none"});
    for (const std::string& mutant : mutants)
      for (const CatalogueEntry& scene : catalogue)
        plan.tasks.push_back({scene.file.caseName() + "." + combination.suffix, scene.file.path.string(), mutant});

    out << "run: " << combination.suffix << ": " << plan.tasks.size() << " test(s)" << std::endl;
    CombinationOutcome outcome = runCombination(plan, options, logsDir, combination.suffix, out);
    anyRan = anyRan || outcome.status != BackendStatus::NotSupported;  // an error is present, and fails

    // Flake detection: the model's tests that failed, crashed or timed out
    // run again, just those, in fresh workers, up to --flake-retries times
    // (mutant tasks are meant to fail and are never retried; nor is a backend
    // that is NotSupported or an error, whose every test would do the same).
    std::vector<std::vector<Attempt>> attempts(plan.tasks.size());
    for (std::size_t i = 0; i < plan.tasks.size(); ++i)
      attempts[i].push_back({outcome.results[i], "logs/" + combination.suffix + ".log"});
    for (int retry = 1; retry <= options.flakeRetries && outcome.status == BackendStatus::Ran; ++retry) {
      WorkerPlan retryPlan = plan;
      retryPlan.tasks.clear();
      std::vector<std::size_t> retried;  // plan indices of retryPlan's tasks
      for (std::size_t i = 0; i < plan.tasks.size(); ++i) {
        const WorkerTask& task = plan.tasks[i];
        const Verdict last = rawVerdictOf(attempts[i].back().result);
        if (task.mutant != "none" || !worthRetrying(last, expected.find(task.test))) continue;
        retried.push_back(i);
        retryPlan.tasks.push_back(task);
      }
      if (retried.empty()) break;
      const std::string stem = combination.suffix + ".retry-" + std::to_string(retry);
      out << "run: " << combination.suffix << ": retry " << retry << " of " << options.flakeRetries << ": "
          << retried.size() << " test(s) in a fresh worker" << std::endl;
      const CombinationOutcome again = runCombination(retryPlan, options, logsDir, stem, out);
      outcome.wallSeconds += again.wallSeconds;
      for (std::size_t k = 0; k < retried.size(); ++k)
        attempts[retried[k]].push_back({again.results[k], "logs/" + stem + ".log"});
    }

    std::map<Verdict, int> counted;
    std::map<std::string, std::vector<Json>> mutantResults;
    std::map<std::string, Verdict> cleanVerdicts;
    for (std::size_t i = 0; i < plan.tasks.size(); ++i) {
      const WorkerTask& task = plan.tasks[i];
      if (task.mutant != "none") {
        mutantResults[task.mutant].push_back(outcome.results[i]);
        continue;
      }
      // A test that passed on a retry is a Flake. A retried test's record is
      // that of its last failing attempt (for a Flake, the failure and its
      // evidence; a retry that found the backend gone, NotSupported, does not
      // turn a failure into a skip).
      const std::vector<Attempt>& tries = attempts[i];
      const bool flake = tries.size() > 1 && passed(rawVerdictOf(tries.back().result));
      std::size_t shown = tries.size() - 1;
      while (shown > 0 && !isFailingAttempt(rawVerdictOf(tries[shown].result))) --shown;
      const Json& result = tries[shown].result;
      const Verdict raw = rawVerdictOf(result);
      cleanVerdicts[task.test] = rawVerdictOf(tries.back().result);
      const ExpectedFailure* listed = expected.find(result.value("test", ""));
      const Verdict verdict = flake ? Verdict::Flake : applyExpectation(raw, listed);
      ++counted[verdict];
      if (comparison::isRunFailure(verdict) || (flake && options.flakesFail)) allGood = false;
      Json record = testRecord(*sceneOfCase.at(task.test.substr(0, task.test.rfind('.'))), combination.suffix,
                               result, listed, verdict);
      if (tries.size() > 1) {  // only a retried test has "attempts"
        Json list = Json::array();
        std::string verdicts;
        for (const Attempt& a : tries) {
          const std::string said(comparison::verdictName(rawVerdictOf(a.result)));
          list.push_back({{"raw_verdict", said}, {"message", a.result.value("message", "")}, {"log", a.log}});
          verdicts += (verdicts.empty() ? "" : ", ") + said;
        }
        record["attempts"] = std::move(list);
        if (flake) flakes.push_back(task.test + ": " + verdicts);
      }
      tests.push_back(std::move(record));
    }
    Json mutantCounts = {{"killed", 0}, {"survived", 0}, {"other", 0}};
    for (const std::string& mutant : mutants) {
      MutantOutcome m = mutantRecord(mutant, combination.suffix, outcome.status, mutantResults[mutant], cleanVerdicts);
      // mutant_counts: killed, survived, and "other" for the statuses that prove nothing.
      const bool ownBucket = m.status == MutantStatus::Killed || m.status == MutantStatus::Survived;
      const std::string bucket = ownBucket ? std::string(comparison::mutantStatusName(m.status)) : "other";
      mutantCounts[bucket] = mutantCounts[bucket].get<int>() + 1;
      if (comparison::isRunFailure(m.status)) allGood = false;
      mutantsJson.push_back(std::move(m.record));
    }
    if (comparison::isRunFailure(outcome.status)) allGood = false;
    backendsJson.push_back({{"backend", combination.suffix},
                            {"api_backend", combination.backend},
                            {"driver_option", combination.driver},
                            {"status", comparison::backendStatusName(outcome.status)},
                            {"message", outcome.message},
                            {"device", outcome.device},
                            {"expected_failures_file", joined(expected.files())},
                            {"counts", countsJson(counted)},
                            {"mutant_counts", mutantCounts},
                            {"wall_s", outcome.wallSeconds},
                            {"log", "logs/" + combination.suffix + ".log"}});
    out << "run: " << combination.suffix << ": " << outcome.status;
    if (!outcome.message.empty()) out << " (" << outcome.message << ")";
    for (const Verdict verdict : comparison::kAllVerdicts)
      if (counted[verdict] > 0) out << ", " << counted[verdict] << " " << verdict;
    if (!mutants.empty())
      out << "; mutants: " << mutantCounts["killed"].get<int>() << " killed, " << mutantCounts["survived"].get<int>()
          << " survived";
    out << " (" << std::fixed << std::setprecision(1) << outcome.wallSeconds << " s)" << std::defaultfloat
        << std::endl;
  }

  // The slowest tests, for whoever keeps the run short (Mesa CI prints the same).
  std::vector<std::pair<double, std::string>> times;
  for (const Json& t : tests)
    if (t["timings_ms"].is_object()) times.emplace_back(t["timings_ms"]["total"].get<double>(), t["name"]);
  std::sort(times.begin(), times.end(), std::greater<>());
  if (times.size() > 10) times.resize(10);
  Json slowest = Json::array();
  for (const auto& [ms, name] : times) slowest.push_back({{"name", name}, {"total_ms", ms}});

  const Json results = {{"format", "lightcts-results"},
                        {"version", 1},
                        {"lightcts_revision", revision()},
                        {"started_utc", startedUtc},
                        {"duration_s", std::chrono::duration<double>(Clock::now() - started).count()},
                        {"command", options.commandLine},
                        {"machine", machineJson()},
                        {"scenes_dir", options.scenesDir},
                        {"timeout_s", options.timeoutSeconds},
                        {"flake_retries", options.flakeRetries},
                        {"flakes_fail", options.flakesFail},
                        {"backends", backendsJson},
                        {"tests", tests},
                        {"mutants", mutantsJson},
                        {"slowest", slowest}};
  reports::writeHtmlReport(results, outDir / "report");
  reports::writeJunit(results, outDir / "junit.xml");
  reports::writeRunCsvs(results, outDir);  // results.csv, failures.csv (deqp-runner's lists)
  // Last: its presence says the run finished and the other files are complete.
  imaging::writeFileAtomically(outDir / "results.json", results.dump(1) + "\n");

  // Flakes apart: they passed, so the per-backend lines alone would hide them.
  if (!flakes.empty()) {
    out << "flaky tests (failed, then passed on a retry in a fresh worker; "
        << (options.flakesFail ? "--flakes-fail: they fail this run" : "they fail a run only with --flakes-fail")
        << "):\n";
    for (const std::string& flake : flakes) out << "  " << flake << "\n";
  }
  out << "slowest tests:\n";
  for (const auto& [ms, name] : times) out << "  " << formatMs(ms) << "  " << name << "\n";
  out << "run: results in " << (outDir / "results.json").string() << ", report in "
      << (outDir / "report" / "index.html").string() << std::endl;
  if (!anyRan) {
    err << "lightcts: run: no backend asked for is present here (NotSupported)\n";
    return 3;
  }
  return allGood ? 0 : 1;
}

}  // namespace runner
