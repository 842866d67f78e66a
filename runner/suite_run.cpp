#include "runner/suite_run.h"

#include "comparison/run_status.h"
#include "comparison/verdict.h"
#include "conformance/mutant_killers.h"
#include "conformance/scene_catalogue.h"
#include "runner/evidence_limit.h"
#include "runner/expected_failures.h"
#include "runner/part_run.h"
#include "runner/part_scheduler.h"
#include "runner/run_budgets.h"
#include "runner/run_metadata.h"
#include "runner/run_progress.h"
#include "runner/run_results.h"
#include "runner/test_selection.h"
#include "runner/worker_plan.h"
#include "scene_input/scene_loader.h"
#include "shaders/shader_variant.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <iostream>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <ostream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <thread>

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
  for (const conformance::SceneFile& file : conformance::findSceneFiles(scenesDir)) {
    const lighting::Scene scene = lighting::loadSceneFile(file.path.string());
    // An import's warnings (SPEC 2.1), once per run; the workers stay quiet.
    for (const std::string& warning : scene.warnings) std::cerr << "lightcts: warning: " << warning << "\n";
    catalogue.push_back({file, scene.description});
  }
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

// A mutant is killed on a backend when at least one scene fails with it that
// passes without it (`cleanVerdicts`: the model's raw verdict per test; with
// --mutants-only it is empty and every failing scene counts).
Json mutantRecord(const std::string& mutant, const std::string& suffix, BackendStatus backendStatus,
                  const std::vector<Json>& results, const std::map<std::string, Verdict>& cleanVerdicts) {
  Json killedBy = Json::array();
  Json evidence = nullptr;
  bool crashed = false, timedOut = false;
  for (const Json& r : results) {
    const Verdict raw = rawVerdictOf(r);
    const std::string test = r.value("test", "");
    const auto clean = cleanVerdicts.find(test);
    if (raw == Verdict::Fail && (clean == cleanVerdicts.end() || passed(clean->second))) {
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
  const std::vector<std::string>* killers = conformance::killersOf(mutant);
  return {{"mutant", mutant},
          {"what", what},
          {"backend", suffix},
          {"status", comparison::mutantStatusName(status)},
          {"killers", killers ? *killers : std::vector<std::string>{}},
          {"killed_by", killedBy},
          {"evidence", evidence}};
}

std::string joined(const std::vector<std::string>& items) {
  std::string text;
  for (const std::string& item : items) text += (text.empty() ? "" : ", ") + item;
  return text;
}

bool isKiller(const std::string& mutant, const std::string& caseName) {
  const std::vector<std::string>* killers = conformance::killersOf(mutant);
  return killers && std::find(killers->begin(), killers->end(), caseName) != killers->end();
}

std::string killerList(const std::string& mutant) {
  const std::vector<std::string>* killers = conformance::killersOf(mutant);
  return killers && !killers->empty() ? joined(*killers) : "none in suite/mutant_killers.def";
}

std::string formatMs(double ms) {
  std::ostringstream text;
  text << std::fixed << std::setprecision(ms < 10 ? 2 : 0) << ms << " ms";
  return text.str();
}

// What a combination's parts said together: the device of the first part
// that has one; Error when a part broke, or when some part found the backend
// absent after another had it (a backend gone mid-run); NotSupported only
// when no part found it.
struct CombinationOutcome {
  BackendStatus status = BackendStatus::Ran;
  std::string message;
  Json device = nullptr;
  std::vector<Json> results;  // one per task, in part order
  double workerSeconds = 0;   // the parts' worker time, summed (they may overlap)
};

CombinationOutcome combineParts(const std::vector<const PartOutcome*>& parts) {
  CombinationOutcome outcome;
  bool anyRan = false, anyAbsent = false;
  for (const PartOutcome* part : parts) {
    if (outcome.device.is_null()) outcome.device = part->device;
    outcome.workerSeconds += part->wallSeconds;
    outcome.results.insert(outcome.results.end(), part->results.begin(), part->results.end());
    anyRan = anyRan || part->status == BackendStatus::Ran;
    anyAbsent = anyAbsent || part->status == BackendStatus::NotSupported;
    if (part->status == BackendStatus::Error && outcome.status != BackendStatus::Error) {
      outcome.status = BackendStatus::Error;
      outcome.message = part->message;
    }
  }
  if (outcome.status != BackendStatus::Error && anyAbsent) {
    outcome.status = anyRan ? BackendStatus::Error : BackendStatus::NotSupported;
    for (const PartOutcome* part : parts)
      if (part->status == BackendStatus::NotSupported) {
        outcome.message = (anyRan ? "the backend went away during the run: " : "") + part->message;
        break;
      }
  }
  return outcome;
}

// logs/<suffix>.log: every part's log, in part order, under a line naming
// the part; the part logs go once copied.
void concatenateLogs(const fs::path& logsDir, const std::string& suffix, int parts) {
  std::ofstream all(logsDir / (suffix + ".log"), std::ios::trunc);
  for (int k = 0; k < parts; ++k) {
    const fs::path partLog = logsDir / (suffix + ".part-" + std::to_string(k) + ".log");
    std::ifstream in(partLog);
    all << "== part " << k << " (plan: logs/" << suffix << ".part-" << k << ".plan.json)\n";
    if (in) all << in.rdbuf();
    in.close();
    fs::remove(partLog);
  }
}

// Every task's stage times summed, the mutation check's included (results.json
// keeps per-test times of the model's tests only): where a backend's worker
// time went, references against the rest.
Json taskMilliseconds(const std::vector<Json>& results) {
  double reference = 0, total = 0;
  int timed = 0;
  for (const Json& r : results) {
    if (!r.contains("timings_ms") || !r["timings_ms"].is_object()) continue;
    reference += r["timings_ms"].value("reference", 0.0);
    total += r["timings_ms"].value("total", 0.0);
    ++timed;
  }
  return {{"tasks", timed}, {"reference", reference}, {"total", total}};
}

int resolvedJobs(int jobs) {
  if (jobs > 0) return jobs;
  return int(std::max(1u, std::thread::hardware_concurrency()));
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
  const std::vector<BackendCombination> combinations = selectCombinations(options.backends, options.driver);
  TestSelection selection;
  for (const std::string& glob : options.includes) selection.include(glob);
  for (const std::string& glob : options.excludes) selection.exclude(glob);
  for (const std::string& file : options.caselists) selection.loadCaselist(file);
  const std::vector<std::string> askedMutants = mutantsToRun(options);
  if (options.timeoutSeconds <= 0) throw std::invalid_argument("--timeout must be positive");
  if (options.flakeRetries < 0) throw std::invalid_argument("--flake-retries must be 0 or more");
  if (options.jobs < 0) throw std::invalid_argument("--jobs must be 1 or more (0: one per core)");
  if (options.mutantsOnly && askedMutants.empty())
    throw std::invalid_argument("nothing to run: --mutants-only with --no-mutants");
  if (options.evidenceLimit < 0) throw std::invalid_argument("--evidence-limit must be 0 or more");
  if (options.mutantsAllScenes && options.noMutants)
    throw std::invalid_argument("--mutants-all-scenes checks mutants, and --no-mutants skips them: choose one");
  if (!options.timingsFile.empty() && !options.shard)
    throw std::invalid_argument("--timings balances shards: it needs --shard I/N");
  const std::optional<Timings> timings =
      options.timingsFile.empty() ? std::nullopt : std::optional<Timings>(loadTimings(options.timingsFile));
  const int jobs = resolvedJobs(options.jobs);

  // The selected tests (one scene on one combination), decided once before
  // sharding: the shards of a selection partition exactly the selection.
  std::vector<std::string> testNames;
  for (const BackendCombination& combination : combinations)
    for (const CatalogueEntry& scene : catalogue) testNames.push_back(scene.file.caseName() + "." + combination.suffix);
  const std::vector<bool> selected = selection.select(testNames);

  // The run's units: each selected test with its mutation-check tasks, one
  // per mutant that this scene is to be checked against (its killers, or
  // every scene with --mutants-all-scenes); then this shard's share.
  std::vector<RunUnit> allUnits;
  std::set<std::string> checkedMutants;  // those with a task in the run
  for (std::size_t c = 0, t = 0; c < combinations.size(); ++c)
    for (const CatalogueEntry& scene : catalogue) {
      if (!selected[t++]) continue;
      const std::string test = scene.file.caseName() + "." + combinations[c].suffix;
      RunUnit unit{c, test, {}};
      if (!options.mutantsOnly) unit.tasks.push_back({test, scene.file.path.string(), "none"});
      for (const std::string& mutant : askedMutants)
        if (options.mutantsAllScenes || isKiller(mutant, scene.file.caseName())) {
          unit.tasks.push_back({test, scene.file.path.string(), mutant});
          checkedMutants.insert(mutant);
        }
      if (!unit.tasks.empty()) allUnits.push_back(std::move(unit));
    }
  // The mutants checked: those asked for that have a scene to run (a
  // selection may leave out every killer of some).
  std::vector<std::string> mutants;
  Json mutantsNotChecked = Json::array();  // results.json: a check left out is said, never silent
  for (const std::string& mutant : askedMutants) {
    if (checkedMutants.count(mutant)) {
      mutants.push_back(mutant);
      continue;
    }
    const std::string why = "none of its killers (" + killerList(mutant) + ") is among the selected scenes of " +
                            options.scenesDir;
    if (!options.mutants.empty())
      throw std::invalid_argument("--mutant " + mutant + ": " + why + "; select one, or use --mutants-all-scenes");
    mutantsNotChecked.push_back({{"mutant", mutant}, {"reason", why}});
  }
  if (allUnits.empty()) throw std::invalid_argument("nothing to run: the selection holds no killer of any mutant");
  // --list keeps stdout for test names alone, so that it reads back as a caselist.
  std::ostream& notes = options.listOnly ? err : out;
  if (!mutantsNotChecked.empty())
    notes << "run: " << mutantsNotChecked.size() << " mutant(s) not checked: the selected scenes hold none of their "
          << "killers (results.json: mutants_not_checked)" << std::endl;
  std::vector<RunUnit> units;
  Json shardJson = nullptr;
  if (options.shard) {
    const std::vector<int> shardOf = assignShards(unitCosts(allUnits, timings), options.shard->total);
    std::size_t runTests = 0;
    for (std::size_t u = 0; u < allUnits.size(); ++u) {
      runTests += options.mutantsOnly ? 0 : 1;
      if (shardOf[u] == options.shard->index - 1) units.push_back(allUnits[u]);
    }
    shardJson = {{"index", options.shard->index},
                 {"total", options.shard->total},
                 {"partition", partitionDigest(allUnits, shardOf, options.shard->total)},
                 {"balanced_by", timings ? "timings" : "test count"},
                 {"timings_file", options.timingsFile},
                 {"tests_in_run", runTests},
                 {"units", units.size()},
                 {"units_in_run", allUnits.size()}};
  } else {
    units = std::move(allUnits);
  }
  if (options.listOnly) {  // the selection as it would run: one test a line (a caselist), the count apart
    std::size_t mutantTasks = 0;
    for (const RunUnit& unit : units) {
      out << unit.test << "\n";
      mutantTasks += std::size_t(std::count_if(unit.tasks.begin(), unit.tasks.end(),
                                               [](const WorkerTask& task) { return task.mutant != "none"; }));
    }
    err << "run: " << units.size() << " test(s), " << mutantTasks << " mutation-check task(s)" << std::endl;
    return 0;
  }
  // The mutants this shard checks on each combination: a shard writes no
  // record of a mutant none of whose tasks it holds (merge joins the others').
  std::set<std::pair<std::string, std::size_t>> shardMutantChecks;
  for (const RunUnit& unit : units)
    for (const WorkerTask& task : unit.tasks)
      if (task.mutant != "none") shardMutantChecks.emplace(task.mutant, unit.combination);
  std::vector<fs::path> sceneFiles;
  for (const CatalogueEntry& scene : catalogue) sceneFiles.push_back(scene.file.path);
  Json baselines = Json::array();  // every file that decided how this run was judged or chosen
  for (const std::string& file : options.expectedFailureFiles) baselines.push_back(baselineFileJson("expected-failures", file));
  for (const std::string& file : options.caselists) baselines.push_back(baselineFileJson("caselist", file));
  const std::string sceneDigest = scenesDigest(sceneFiles, options.scenesDir);

  const fs::path outDir(options.outDir);
  const fs::path logsDir = outDir / "logs";
  fs::create_directories(logsDir);
  removeStaleRunOutputs(outDir);
  const bool privateCache = options.freshReferences || options.referenceCache.empty();
  const fs::path referenceCache = privateCache ? fs::absolute(outDir / "reference-cache") : fs::path(options.referenceCache);
  if (privateCache) fs::remove_all(referenceCache);

  // The parts, and what each combination has to do.
  const std::vector<WorkerPart> parts = workerParts(units, combinations.size());
  std::vector<std::size_t> taskTotals(combinations.size(), 0);
  std::vector<int> partCounts(combinations.size(), 0);
  for (const WorkerPart& part : parts) {
    taskTotals[part.combination] += part.tasks.size();
    ++partCounts[part.combination];
  }
  std::vector<std::string> names;
  for (const BackendCombination& c : combinations) names.push_back(c.suffix);
  for (std::size_t c = 0; c < combinations.size(); ++c)
    if (taskTotals[c] > 0) out << "run: " << names[c] << ": " << taskTotals[c] << " test(s)" << std::endl;
  out << "run: " << parts.size() << " worker part(s), up to " << jobs << " at once"
      << (options.shard ? ", shard " + std::to_string(options.shard->index) + "/" +
                              std::to_string(options.shard->total)
                        : std::string())
      << std::endl;

  RunProgress progress(out, options.progressInPlace, names, taskTotals);
  const auto timeout = std::chrono::milliseconds(static_cast<long long>(options.timeoutSeconds * 1000));
  auto planOf = [&](std::size_t combination, std::vector<WorkerTask> tasks) {
    return WorkerPlan{combinations[combination], options.device,         options.expectDriver,
                      fs::absolute(outDir).string(), referenceCache.string(), std::move(tasks)};
  };
  auto callbacksOf = [&](std::size_t combination) {
    PartCallbacks callbacks;
    callbacks.taskDone = [&progress, &expected, combination](const WorkerTask& task, const Json& result) {
      const Verdict raw = rawVerdictOf(result);
      const bool failed = task.mutant == "none" &&
                          comparison::isRunFailure(applyExpectation(raw, expected.find(task.test)));
      progress.taskDone(combination, failed);
    };
    callbacks.note = [&progress](const std::string& line) { progress.note(line); };
    return callbacks;
  };

  // Every part, up to --jobs at once (runner/part_scheduler.h).
  std::vector<PartOutcome> partOutcomes(parts.size());
  runPartsInParallel(
      parts, jobs,
      [&](std::size_t p, const std::function<void()>& backendUp) {
        const WorkerPart& part = parts[p];
        PartCallbacks callbacks = callbacksOf(part.combination);
        callbacks.backendUp = backendUp;
        partOutcomes[p] = runPart(planOf(part.combination, part.tasks), options.workerExecutable, timeout, logsDir,
                                  names[part.combination] + ".part-" + std::to_string(part.number), callbacks);
      },
      [&](std::size_t p, std::size_t firstPart) {
        // The combination's first part never got its backend up: every other
        // part would do the same, so its tasks take that part's verdict.
        const PartOutcome& first = partOutcomes[firstPart];
        PartOutcome skipped;
        skipped.status = first.status;
        skipped.message = first.message;
        const Json said = first.results.empty()
                              ? abnormalResult(parts[p].tasks.front(), Verdict::Crash, "its first worker part failed")
                              : first.results.back();
        const Verdict verdict = rawVerdictOf(said);
        for (const WorkerTask& task : parts[p].tasks)
          skipped.results.push_back(abnormalResult(task, verdict, said.value("message", "")));
        progress.tasksSkipped(parts[p].combination, parts[p].tasks.size());
        partOutcomes[p] = std::move(skipped);
      });
  for (std::size_t c = 0; c < combinations.size(); ++c)
    if (partCounts[c] > 0) concatenateLogs(logsDir, names[c], partCounts[c]);

  std::vector<CombinationOutcome> outcomes(combinations.size());
  std::vector<std::vector<WorkerTask>> planTasks(combinations.size());
  for (std::size_t c = 0; c < combinations.size(); ++c) {
    std::vector<const PartOutcome*> mine;
    for (std::size_t p = 0; p < parts.size(); ++p)
      if (parts[p].combination == c) {
        mine.push_back(&partOutcomes[p]);
        planTasks[c].insert(planTasks[c].end(), parts[p].tasks.begin(), parts[p].tasks.end());
      }
    outcomes[c] = combineParts(mine);
  }

  // Flake detection: the model's tests that failed, crashed or timed out
  // run again, just those, in fresh workers, up to --flake-retries times
  // (mutant tasks are meant to fail and are never retried; nor is a backend
  // that is NotSupported or an error, whose every test would do the same).
  // Each round retries every combination's tests, one worker per
  // combination, up to --jobs at once.
  std::vector<std::vector<std::vector<Attempt>>> attempts(combinations.size());
  for (std::size_t c = 0; c < combinations.size(); ++c)
    for (const Json& result : outcomes[c].results) attempts[c].push_back({{result, "logs/" + names[c] + ".log"}});
  for (int retry = 1; retry <= options.flakeRetries; ++retry) {
    std::vector<WorkerPart> retryParts;
    std::vector<std::vector<std::size_t>> retried;  // per retry part, the plan indices of its tasks
    for (std::size_t c = 0; c < combinations.size(); ++c) {
      if (outcomes[c].status != BackendStatus::Ran) continue;
      WorkerPart part{c, retry, {}};
      std::vector<std::size_t> indices;
      for (std::size_t i = 0; i < planTasks[c].size(); ++i) {
        const WorkerTask& task = planTasks[c][i];
        const Verdict last = rawVerdictOf(attempts[c][i].back().result);
        if (task.mutant != "none" || !worthRetrying(last, expected.find(task.test))) continue;
        indices.push_back(i);
        part.tasks.push_back(task);
      }
      if (indices.empty()) continue;
      progress.note("run: " + names[c] + ": retry " + std::to_string(retry) + " of " +
                    std::to_string(options.flakeRetries) + ": " + std::to_string(indices.size()) +
                    " test(s) in a fresh worker");
      retryParts.push_back(std::move(part));
      retried.push_back(std::move(indices));
    }
    if (retryParts.empty()) break;
    std::vector<PartOutcome> again(retryParts.size());
    PartCallbacks quiet;
    quiet.note = [&progress](const std::string& line) { progress.note(line); };
    runPartsInParallel(
        retryParts, jobs,
        [&](std::size_t p, const std::function<void()>&) {
          const std::size_t c = retryParts[p].combination;
          again[p] = runPart(planOf(c, retryParts[p].tasks), options.workerExecutable, timeout, logsDir,
                             names[c] + ".retry-" + std::to_string(retry), quiet);
        },
        nullptr);
    for (std::size_t p = 0; p < retryParts.size(); ++p) {
      const std::size_t c = retryParts[p].combination;
      outcomes[c].workerSeconds += again[p].wallSeconds;
      for (std::size_t k = 0; k < retried[p].size(); ++k)
        attempts[c][retried[p][k]].push_back(
            {again[p].results[k], "logs/" + names[c] + ".retry-" + std::to_string(retry) + ".log"});
    }
  }
  progress.finish();
  if (privateCache) fs::remove_all(referenceCache);

  Json backendsJson = Json::array();
  Json tests = Json::array();
  Json mutantsJson = Json::array();
  bool anyRan = false, allGood = true;
  std::vector<std::string> flakes;     // "test: Crash, Pass", for the summary
  std::vector<std::string> summaries;  // one line per combination
  std::map<std::string, const CatalogueEntry*> sceneOfCase;
  for (const CatalogueEntry& scene : catalogue) sceneOfCase[scene.file.caseName()] = &scene;

  for (std::size_t c = 0; c < combinations.size(); ++c) {
    if (taskTotals[c] == 0) continue;  // a shard without this combination's scenes
    const BackendCombination& combination = combinations[c];
    const CombinationOutcome& outcome = outcomes[c];
    anyRan = anyRan || outcome.status != BackendStatus::NotSupported;  // an error is present, and fails
    std::map<Verdict, int> counted;
    std::map<std::string, std::vector<Json>> mutantResults;
    std::map<std::string, Verdict> cleanVerdicts;
    for (std::size_t i = 0; i < planTasks[c].size(); ++i) {
      const WorkerTask& task = planTasks[c][i];
      if (task.mutant != "none") {
        mutantResults[task.mutant].push_back(outcome.results[i]);
        continue;
      }
      // A test that passed on a retry is a Flake. A retried test's record is
      // that of its last failing attempt (for a Flake, the failure and its
      // evidence; a retry that found the backend gone, NotSupported, does not
      // turn a failure into a skip).
      const std::vector<Attempt>& tries = attempts[c][i];
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
    std::vector<const Json*> mutantRecords;
    const std::size_t firstMutant = mutantsJson.size();
    for (const std::string& mutant : mutants) {
      if (!shardMutantChecks.count({mutant, c})) continue;  // none of its scenes is here on this combination
      Json m = mutantRecord(mutant, combination.suffix, outcome.status, mutantResults[mutant], cleanVerdicts);
      const MutantStatus status = *comparison::parseMutantStatus(m["status"].get<std::string>());
      // In a shard, a mutant that survives this shard's scenes may be killed
      // by another shard's: only the merged run can say it survived.
      const bool provesNothingYet = options.shard && status == MutantStatus::Survived;
      if (comparison::isRunFailure(status) && !provesNothingYet) allGood = false;
      mutantsJson.push_back(std::move(m));
    }
    for (std::size_t k = firstMutant; k < mutantsJson.size(); ++k) mutantRecords.push_back(&mutantsJson[k]);
    const Json mutantCounts = mutantCountsJson(mutantRecords);
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
                            {"wall_s", outcome.workerSeconds},
                            {"task_ms", taskMilliseconds(outcome.results)},
                            {"log", "logs/" + combination.suffix + ".log"}});
    std::ostringstream line;
    line << "run: " << combination.suffix << ": " << outcome.status;
    if (!outcome.message.empty()) line << " (" << outcome.message << ")";
    for (const Verdict verdict : comparison::kAllVerdicts)
      if (counted[verdict] > 0) line << ", " << counted[verdict] << " " << verdict;
    if (!mutants.empty())
      line << "; mutants: " << mutantCounts["killed"].get<int>() << " killed, "
           << mutantCounts["survived"].get<int>() << " survived";
    line << " (" << std::fixed << std::setprecision(1) << outcome.workerSeconds << " s in workers)";
    summaries.push_back(line.str());
  }

  // SPEC 5.5 for the report: once per scene this run (or shard) holds,
  // whatever the backends; mutant-only runs check no scene of their own.
  Json budgets = Json::object();
  if (!options.noBudgets && !options.mutantsOnly) {
    const auto budgetStart = Clock::now();
    std::set<std::string> heldCases;
    for (const RunUnit& unit : units) heldCases.insert(unit.test.substr(0, unit.test.rfind('.')));
    std::vector<BudgetScene> budgetScenes;
    for (const CatalogueEntry& scene : catalogue)
      if (heldCases.contains(scene.file.caseName())) budgetScenes.push_back({scene.file.caseName(), scene.file.path});
    budgets = runBudgets(budgetScenes, outDir);
    summaries.push_back("run: light budgets of " + std::to_string(budgetScenes.size()) + " scene(s) in " +
                        formatMs(std::chrono::duration<double, std::milli>(Clock::now() - budgetStart).count()));
  }
  const long long imagesDropped = limitEvidenceImages(tests, outDir, options.evidenceLimit);
  const Json slowest = slowestTests(tests);
  const Json results = {{"format", "lightcts-results"},
                        {"version", 1},
                        {"lightcts_revision", revision()},
                        {"started_utc", startedUtc},
                        {"duration_s", std::chrono::duration<double>(Clock::now() - started).count()},
                        {"command", options.commandLine},
                        {"machine", machineJson()},
                        {"scenes_dir", options.scenesDir},
                        {"scenes_digest", sceneDigest},
                        {"selection", selection.toJson()},
                        {"baseline_files", baselines},
                        {"mutants_run", mutants},
                        {"mutant_check", options.mutantsAllScenes ? "all-scenes" : "killers"},
                        {"mutants_not_checked", mutantsNotChecked},
                        {"evidence_limit", options.evidenceLimit},
                        {"evidence_url", options.evidenceUrl},
                        {"jobs", jobs},
                        {"shard", shardJson},
                        {"reference_cache", privateCache ? Json("fresh") : Json(referenceCache.string())},
                        {"timeout_s", options.timeoutSeconds},
                        {"flake_retries", options.flakeRetries},
                        {"flakes_fail", options.flakesFail},
                        {"backends", backendsJson},
                        {"tests", tests},
                        {"mutants", mutantsJson},
                        {"budgets", budgets},
                        {"slowest", slowest}};
  writeRunOutputs(results, outDir);

  for (const std::string& line : summaries) out << line << "\n";
  // Flakes apart: they passed, so the per-backend lines alone would hide them.
  if (!flakes.empty()) {
    out << "flaky tests (failed, then passed on a retry in a fresh worker; "
        << (options.flakesFail ? "--flakes-fail: they fail this run" : "they fail a run only with --flakes-fail")
        << "):\n";
    for (const std::string& flake : flakes) out << "  " << flake << "\n";
  }
  if (imagesDropped > 0)
    out << "run: " << imagesDropped << " failure(s) past --evidence-limit " << options.evidenceLimit
        << " keep their numbers (summary.json) but no images\n";
  out << "slowest tests:\n";
  for (const Json& s : slowest) out << "  " << formatMs(s["total_ms"].get<double>()) << "  " << s["name"].get<std::string>() << "\n";
  out << "run: results in " << (outDir / "results.json").string() << ", report in "
      << (outDir / "report" / "index.html").string() << std::endl;
  if (options.shard && units.empty()) {  // a small selection cut into many shards
    out << "run: shard " << options.shard->index << "/" << options.shard->total
        << " holds no test of this selection" << std::endl;
    return 0;
  }
  if (!anyRan) {
    err << "lightcts: run: no backend asked for is present here (NotSupported)\n";
    return 3;
  }
  return allGood ? 0 : 1;
}

}  // namespace runner
