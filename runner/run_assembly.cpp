#include "runner/run_assembly.h"

#include "conformance/scene_lists.h"
#include "reports/result_fields.h"
#include "results/result_rules.h"

#include <map>

namespace runner {
namespace {

using Json = nlohmann::ordered_json;
using comparison::BackendStatus;
using comparison::Verdict;

// A model test's record. A test that passed on a retry is a Flake. A
// retried test's record is that of its last failing attempt (for a Flake,
// the failure and its evidence; a retry that found the backend gone,
// NotSupported, does not turn a failure into a skip).
results::TestRecord testRecord(const CatalogueEntry& scene, const WorkerTask& task, const std::string& suffix,
                               const std::vector<Attempt>& tries, const ExpectedFailure* listed) {
  const bool flake = tries.size() > 1 && results::passed(tries.back().result.rawVerdict);
  std::size_t shown = tries.size() - 1;
  while (shown > 0 && !results::failedAttempt(tries[shown].result.rawVerdict)) --shown;
  const results::TaskResult& result = tries[shown].result;
  results::TestRecord record;
  record.name = result.test;
  record.group = scene.file.group;
  record.scene = scene.file.name;
  record.sceneFile = scene.file.path.string();
  record.description = scene.description;
  record.backend = suffix;
  if (task.admissible != shaders::Admissible::None) record.admissible = std::string(shaders::admissibleName(task.admissible));
  record.rawVerdict = result.rawVerdict;
  record.verdict = flake ? Verdict::Flake : applyExpectation(result.rawVerdict, listed);
  record.expectedReason = listed ? listed->reason : "";
  static_cast<results::TaskOutcome&>(record) = result;
  if (tries.size() > 1)  // only a retried test has "attempts"
    for (const Attempt& a : tries) record.attempts.push_back({a.result.rawVerdict, a.result.message, a.log});
  return record;
}

// A mutant is killed on a backend when at least one scene fails with it that
// passes without it (`cleanVerdicts`: the model's last raw verdict per test;
// with --mutants-only it is empty and every failing scene counts).
results::MutantRecord mutantRecord(shaders::Mutant mutant, const std::string& suffix, BackendStatus backendStatus,
                                   const std::vector<const results::TaskResult*>& tasks,
                                   const std::map<std::string, Verdict>& cleanVerdicts) {
  results::MutantRecord record;
  record.mutant = std::string(shaders::mutantName(mutant));
  record.backend = suffix;
  results::MutantObservations seen;
  seen.backendAbsent = backendStatus == BackendStatus::NotSupported;
  for (const results::TaskResult* r : tasks) {
    const auto clean = cleanVerdicts.find(r->test);
    if (r->rawVerdict == Verdict::Fail && (clean == cleanVerdicts.end() || results::passed(clean->second))) {
      record.killedBy.push_back(r->test.substr(0, r->test.rfind('.')));
      if (!record.evidence && r->evidence) {
        record.evidence = r->evidence;
        record.evidence->test = r->test;
      }
    }
    seen.crashed = seen.crashed || r->rawVerdict == Verdict::Crash;
    seen.timedOut = seen.timedOut || r->rawVerdict == Verdict::Timeout;
    seen.notRun = seen.notRun || r->rawVerdict == Verdict::NotRun;
  }
  seen.killed = !record.killedBy.empty();
  record.status = results::mutantStatus(seen);
  for (const shaders::MutantName& m : shaders::mutantNames())
    if (m.mutant == mutant) record.what = std::string(m.what);
  if (const std::vector<std::string>* killers = conformance::killersOf(record.mutant)) record.killers = *killers;
  return record;
}

}  // namespace

AssembledRecords assembleRecords(const RunInputs& inputs, const RunUnits& plan, const std::vector<CombinationRun>& runs) {
  AssembledRecords records;
  std::map<std::string, const CatalogueEntry*> sceneOfCase;
  for (const CatalogueEntry& scene : inputs.catalogue) sceneOfCase[scene.file.caseName()] = &scene;
  for (std::size_t c = 0; c < runs.size(); ++c) {
    const CombinationRun& run = runs[c];
    if (run.tasks.empty()) continue;  // a shard without this combination's scenes
    const BackendCombination& combination = inputs.combinations[c];
    std::map<shaders::Mutant, std::vector<const results::TaskResult*>> mutantTasks;
    std::map<std::string, Verdict> cleanVerdicts;
    for (std::size_t i = 0; i < run.tasks.size(); ++i) {
      const WorkerTask& task = run.tasks[i];
      const std::vector<Attempt>& tries = run.attempts[i];
      if (task.isMutantTask()) {
        mutantTasks[task.mutant].push_back(&tries.front().result);
        continue;
      }
      if (task.isModelTest()) cleanVerdicts[task.test] = tries.back().result.rawVerdict;
      results::TestRecord record = testRecord(*sceneOfCase.at(caseOfTest(task.test)), task, combination.suffix, tries,
                                              inputs.expected.find(task.test));
      if (record.verdict == Verdict::Flake) {
        std::string verdicts;
        for (const Attempt& a : tries)
          verdicts += (verdicts.empty() ? "" : ", ") + std::string(comparison::verdictName(a.result.rawVerdict));
        records.flakes.push_back(task.test + ": " + verdicts);
      }
      records.tests.push_back(std::move(record));
    }
    for (const shaders::Mutant mutant : plan.mutants) {
      if (!plan.mutantChecks.count({mutant, c})) continue;  // none of its scenes is here on this combination
      records.mutants.push_back(
          mutantRecord(mutant, combination.suffix, run.status.status, mutantTasks[mutant], cleanVerdicts));
    }
    results::BackendRecord backend;
    backend.backend = combination.suffix;
    backend.apiBackend = combination.backend;
    backend.driverOption = combination.driver;
    backend.status = run.status.status;
    backend.message = run.status.message;
    backend.device = run.device;
    backend.expectedFailuresFile = reports::joined(inputs.expected.files());
    backend.counts = results::countVerdicts(records.tests, combination.suffix);
    backend.admissibleCounts = results::countAdmissibleVerdicts(records.tests, combination.suffix);
    backend.mutantCounts = results::countMutants(records.mutants, combination.suffix);
    backend.wallSeconds = run.workerSeconds;
    backend.taskTimes = run.taskTimes;
    backend.log = "logs/" + combination.suffix + ".log";
    records.backends.push_back(std::move(backend));
  }
  return records;
}

}  // namespace runner
