#include "runner/run_execution.h"

#include "runner/part_run.h"
#include "runner/part_scheduler.h"
#include "runner/run_interruption.h"
#include "runner/run_progress.h"

#include <chrono>
#include <fstream>
#include <ostream>

namespace runner {
namespace {

namespace fs = std::filesystem;
using comparison::BackendStatus;
using comparison::Verdict;

// Flake detection (docs/results-format.md): an attempt that failed, crashed
// or timed out, and not as the test's expected-failures line says (a known
// failure is not retried), is worth another in a fresh worker. An attempt
// that passes, QualityWarning included, ends the retries.
bool worthRetrying(Verdict raw, const ExpectedFailure* listed) {
  return results::failedAttempt(raw) && comparison::isRunFailure(applyExpectation(raw, listed));
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

class Execution {
 public:
  Execution(const RunOptions& options, const RunInputs& inputs, const WorkerSetting& setting)
      : options_(options), inputs_(inputs), setting_(setting), logsDir_(setting.outDir / "logs"),
        timeout_(static_cast<long long>(options.timeoutSeconds * 1000)) {
    for (const BackendCombination& c : inputs.combinations) names_.push_back(c.suffix);
  }

  // Every part, up to --jobs at once; a combination whose first part never
  // got its backend up gives its other tasks that part's verdict.
  std::vector<CombinationRun> firstAttempts(const std::vector<WorkerPart>& parts, RunProgress& progress) {
    std::vector<PartOutcome> outcomes(parts.size());
    runPartsInParallel(
        parts, inputs_.jobs,
        [&](std::size_t p, const std::function<void()>& backendUp) {
          const WorkerPart& part = parts[p];
          PartCallbacks callbacks;
          callbacks.taskDone = [&progress, this, c = part.combination](const WorkerTask& task,
                                                                       const results::TaskResult& result) {
            const bool failed = !task.isMutantTask() && comparison::isRunFailure(applyExpectation(
                                                          result.rawVerdict, inputs_.expected.find(task.test)));
            progress.taskDone(c, failed);
          };
          callbacks.note = [&progress](const std::string& line) { progress.note(line); };
          callbacks.backendUp = backendUp;
          outcomes[p] = runPart(planOf(part.combination, part.tasks), options_.workerExecutable, timeout_, logsDir_,
                                names_[part.combination] + ".part-" + std::to_string(part.number), callbacks);
        },
        [&](std::size_t p, std::size_t firstPart) {
          const PartOutcome& first = outcomes[firstPart];
          PartOutcome skipped;
          skipped.status = first.status;
          skipped.message = first.message;
          const results::TaskResult said =
              first.results.empty()
                  ? results::TaskResult::abnormal(parts[p].tasks.front().test, Verdict::Crash,
                                                  "its first worker part failed")
                  : first.results.back();
          for (const WorkerTask& task : parts[p].tasks)
            skipped.results.push_back(results::TaskResult::abnormal(task.test, said.rawVerdict, said.message));
          progress.tasksSkipped(parts[p].combination, parts[p].tasks.size());
          outcomes[p] = std::move(skipped);
        });
    std::vector<CombinationRun> runs(inputs_.combinations.size());
    for (std::size_t c = 0; c < runs.size(); ++c) {
      std::vector<results::StatusAndMessage> statuses;
      int partCount = 0;
      for (std::size_t p = 0; p < parts.size(); ++p) {
        if (parts[p].combination != c) continue;
        PartOutcome& part = outcomes[p];
        ++partCount;
        statuses.push_back({part.status, part.message});
        if (!runs[c].device) runs[c].device = part.device;
        runs[c].workerSeconds += part.wallSeconds;
        runs[c].tasks.insert(runs[c].tasks.end(), parts[p].tasks.begin(), parts[p].tasks.end());
        runs[c].taskTimes += results::taskTimesOf(part.results);
        for (results::TaskResult& result : part.results)
          runs[c].attempts.push_back({{std::move(result), "logs/" + names_[c] + ".log"}});
      }
      if (partCount > 0) concatenateLogs(logsDir_, names_[c], partCount);
      runs[c].status = results::combinedBackendStatus(statuses, "the backend went away during the run: ");
    }
    return runs;
  }

  // The tests (the model's and the admissible variants') that failed,
  // crashed or timed out run again, just those, up to --flake-retries times (mutant tasks are meant to fail and
  // are never retried; nor is a backend that is NotSupported or in error,
  // whose every test would do the same). Each round retries every
  // combination's tests, one worker per combination, up to --jobs at once.
  void retryFailures(std::vector<CombinationRun>& runs, RunProgress& progress) {
    for (int retry = 1; retry <= options_.flakeRetries; ++retry) {
      if (interruptingSignal() != 0) return;  // an interrupted run retries nothing
      std::vector<WorkerPart> retryParts;
      std::vector<std::vector<std::size_t>> retried;  // per retry part, the indices of its tasks
      for (std::size_t c = 0; c < runs.size(); ++c) {
        if (runs[c].status.status != BackendStatus::Ran) continue;
        WorkerPart part{c, retry, {}};
        std::vector<std::size_t> indices;
        for (std::size_t i = 0; i < runs[c].tasks.size(); ++i) {
          const WorkerTask& task = runs[c].tasks[i];
          const Verdict last = runs[c].attempts[i].back().result.rawVerdict;
          if (task.isMutantTask() || !worthRetrying(last, inputs_.expected.find(task.test))) continue;
          indices.push_back(i);
          part.tasks.push_back(task);
        }
        if (indices.empty()) continue;
        progress.note("run: " + names_[c] + ": retry " + std::to_string(retry) + " of " +
                      std::to_string(options_.flakeRetries) + ": " + std::to_string(indices.size()) +
                      " test(s) in a fresh worker");
        retryParts.push_back(std::move(part));
        retried.push_back(std::move(indices));
      }
      if (retryParts.empty()) return;
      std::vector<PartOutcome> again(retryParts.size());
      PartCallbacks quiet;
      quiet.note = [&progress](const std::string& line) { progress.note(line); };
      runPartsInParallel(
          retryParts, inputs_.jobs,
          [&](std::size_t p, const std::function<void()>&) {
            const std::size_t c = retryParts[p].combination;
            again[p] = runPart(planOf(c, retryParts[p].tasks), options_.workerExecutable, timeout_, logsDir_,
                               names_[c] + ".retry-" + std::to_string(retry), quiet);
          },
          nullptr);
      for (std::size_t p = 0; p < retryParts.size(); ++p) {
        const std::size_t c = retryParts[p].combination;
        runs[c].workerSeconds += again[p].wallSeconds;
        for (std::size_t k = 0; k < retried[p].size(); ++k)
          runs[c].attempts[retried[p][k]].push_back(
              {again[p].results[k], "logs/" + names_[c] + ".retry-" + std::to_string(retry) + ".log"});
      }
    }
  }

  const std::vector<std::string>& names() const { return names_; }

 private:
  WorkerPlan planOf(std::size_t combination, std::vector<WorkerTask> tasks) const {
    return WorkerPlan{inputs_.combinations[combination],
                      options_.device,
                      options_.expectDriver,
                      fs::absolute(setting_.outDir).string(),
                      setting_.referenceCache.string(),
                      options_.measureSharpness,
                      std::move(tasks)};
  }

  const RunOptions& options_;
  const RunInputs& inputs_;
  const WorkerSetting& setting_;
  const fs::path logsDir_;
  const std::chrono::milliseconds timeout_;
  std::vector<std::string> names_;
};

}  // namespace

std::vector<CombinationRun> executeRun(const RunOptions& options, const RunInputs& inputs, const RunUnits& plan,
                                       const WorkerSetting& setting, std::ostream& out) {
  Execution execution(options, inputs, setting);
  const std::vector<WorkerPart> parts =
      workerParts(plan.units, inputs.combinations.size(), std::size_t(options.testsPerWorker));
  std::vector<std::size_t> taskTotals(inputs.combinations.size(), 0);
  for (const WorkerPart& part : parts) taskTotals[part.combination] += part.tasks.size();
  const std::vector<std::string>& names = execution.names();
  for (std::size_t c = 0; c < names.size(); ++c)
    if (taskTotals[c] > 0) out << "run: " << names[c] << ": " << taskTotals[c] << " test(s)" << std::endl;
  out << "run: " << parts.size() << " worker part(s), up to " << inputs.jobs << " at once"
      << (options.shard ? ", shard " + std::to_string(options.shard->index) + "/" +
                              std::to_string(options.shard->total)
                        : std::string())
      << std::endl;
  RunProgress progress(out, options.progressInPlace, names, taskTotals);
  std::vector<CombinationRun> runs = execution.firstAttempts(parts, progress);
  execution.retryFailures(runs, progress);
  progress.finish();
  return runs;
}

}  // namespace runner
