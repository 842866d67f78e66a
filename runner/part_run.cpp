#include "runner/part_run.h"

#include "app/exit_status.h"
#include "comparison/verdict.h"
#include "imaging/atomic_file.h"
#include "runner/run_interruption.h"
#include "runner/worker_process.h"
#include "runner/worker_protocol.h"

#include <csignal>
#include <fstream>
#include <sstream>

namespace runner {
namespace {

using Json = nlohmann::ordered_json;
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
using comparison::BackendStatus;
using comparison::Verdict;

// How long a worker's end by SIGINT or SIGTERM waits for the same signal to
// reach the run: far longer than a signal takes, and paid only by a worker
// someone else signalled.
constexpr std::chrono::milliseconds kSignalGrace{1000};

std::string lastLines(const fs::path& file, int count) {
  std::ifstream in(file);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  std::string text;
  for (std::size_t i = lines.size() > std::size_t(count) ? lines.size() - count : 0; i < lines.size(); ++i)
    text += lines[i] + "\n";
  return text;
}

std::string verdictLine(Verdict verdict, const std::string& test, const std::string& how) {
  std::ostringstream text;
  text << "  " << verdict << " " << test;
  if (!how.empty()) text << " (" << how << ")";
  return text.str();
}

// The record of a task that never got a worker's result.
results::TaskResult abnormalResult(const WorkerTask& task, Verdict verdict, const std::string& message) {
  return results::TaskResult::abnormal(task.test, verdict, message);
}

}  // namespace

PartOutcome runPart(const WorkerPlan& plan, const std::string& workerExecutable, std::chrono::milliseconds timeout,
                    const fs::path& logsDir, const std::string& fileStem, const PartCallbacks& callbacks) {
  PartOutcome outcome;
  const auto start = Clock::now();
  const fs::path planFile = logsDir / (fileStem + ".plan.json");
  imaging::writeFileAtomically(planFile, planToJson(plan).dump(1) + "\n");
  const fs::path logFile = logsDir / (fileStem + ".log");
  fs::remove(logFile);  // the workers append; an earlier run's lines are not this run's

  auto record = [&](const WorkerTask& task, results::TaskResult result) {
    if (callbacks.taskDone) callbacks.taskDone(task, result);
    outcome.results.push_back(std::move(result));
  };
  auto note = [&](const std::string& line) {
    if (callbacks.note) callbacks.note(line);
  };

  // Interrupted (runner/run_interruption.h): the tasks from `next` on are NotRun.
  auto recordNotRun = [&](std::size_t from) {
    const std::string message =
        std::string("not run: the run was interrupted by ") + signalName(interruptingSignal()) + " first";
    for (std::size_t i = from; i < plan.tasks.size(); ++i)
      record(plan.tasks[i], abnormalResult(plan.tasks[i], Verdict::NotRun, message));
  };

  std::size_t next = 0;
  while (next < plan.tasks.size()) {
    if (interruptingSignal() != 0) {
      recordNotRun(next);
      break;
    }
    WorkerProcess worker({workerExecutable, "worker", "--plan", planFile.string(), "--start", std::to_string(next)},
                         logFile.string());
    std::string line;
    bool stop = false;
    bool gotResult = false;  // this worker reported at least one test
    bool backendUp = false;  // this worker said "device": its backend was created
    for (;;) {
      auto status = worker.readLine(timeout, line);
      std::string endedHow;
      if (status == WorkerProcess::ReadStatus::Closed) endedHow = worker.finish(false);
      // A worker that ended or went quiet with the run's signal did not
      // crash: NotRun. One that SIGINT or SIGTERM ended was likely sent it
      // with the run, which may not have taken it yet.
      const int endedBy = worker.endingSignal();
      const auto grace = endedBy == SIGINT || endedBy == SIGTERM ? kSignalGrace : std::chrono::milliseconds(0);
      if (status != WorkerProcess::ReadStatus::Line && runInterrupted(grace))
        status = WorkerProcess::ReadStatus::Interrupted;
      if (status == WorkerProcess::ReadStatus::Interrupted) {
        worker.finish(true);
        recordNotRun(next);
        next = plan.tasks.size();
        break;
      }
      if (status != WorkerProcess::ReadStatus::Line && !backendUp) {
        const bool hung = status == WorkerProcess::ReadStatus::TimedOut;
        const std::string how = hung ? worker.finish(true) : endedHow;
        outcome.status = BackendStatus::Error;
        outcome.message = std::string(hung ? "the backend did not start within the timeout" : "the worker ended") +
                          " before its backend was up (" + how + "); its last output:\n" + lastLines(logFile, 8);
        for (; next < plan.tasks.size(); ++next)
          record(plan.tasks[next], abnormalResult(plan.tasks[next], hung ? Verdict::Timeout : Verdict::Crash,
                                                  outcome.message));
        break;
      }
      if (status == WorkerProcess::ReadStatus::TimedOut) {
        const std::string how = worker.finish(true);
        const WorkerTask& task = plan.tasks[next];
        record(task, abnormalResult(task, Verdict::Timeout,
                                    "no result within " + std::to_string(timeout.count() / 1000.0) +
                                        " s; worker " + how));
        note(verdictLine(Verdict::Timeout, task.test, ""));
        ++next;
        break;
      }
      if (status == WorkerProcess::ReadStatus::Closed) {
        const std::string& how = endedHow;
        // An internal error after a test's result: the worker reported a driver
        // error and quit, so that a new one starts on a fresh device. No test is lost.
        if (worker.exitStatus() == app::kExitInternalError && gotResult) break;
        if (next < plan.tasks.size()) {
          const WorkerTask& task = plan.tasks[next];
          record(task, abnormalResult(task, Verdict::Crash,
                                      "the worker ended during this test (" + how + "); its last output:\n" +
                                          lastLines(logFile, 8)));
          note(verdictLine(Verdict::Crash, task.test, how));
          ++next;
        }
        break;
      }
      Json event;
      try {
        event = Json::parse(line);
      } catch (const Json::parse_error&) {
        continue;  // a driver that prints on stdout; the protocol lines are JSON objects
      }
      if (!event.is_object()) continue;
      const std::string kind = event.value(protocol::kKind, "");
      if (kind == protocol::kDevice) {
        outcome.device = results::DeviceRecord::fromJson(event.value(protocol::kDeviceField, Json::object()));
        backendUp = true;
        if (callbacks.backendUp) callbacks.backendUp();
      } else if (kind == protocol::kBackendError && next < plan.tasks.size() && !plan.tasks[next].isModelTest()) {
        // A mutant's or an admissible variant's backend that could not be
        // built (its shaders, its pipelines; the model's ran in the
        // combination's first part): the combination is in error and that
        // variant's tasks crashed; a fresh worker takes the next variant
        // packed into this part, whose verdicts stay its own.
        outcome.status = BackendStatus::Error;
        outcome.message = event.value(protocol::kMessage, "");
        const WorkerTask failed = plan.tasks[next];
        const std::string which = failed.isMutantTask()
                                      ? "mutant " + std::string(shaders::mutantName(failed.mutant))
                                      : "admissible variant " + std::string(shaders::admissibleName(failed.admissible));
        for (; next < plan.tasks.size() && plan.tasks[next].sameShaders(failed); ++next)
          record(plan.tasks[next],
                 abnormalResult(plan.tasks[next], Verdict::Crash, which + ": backend error: " + outcome.message));
        break;
      } else if (kind == protocol::kBackendUnavailable || kind == protocol::kBackendError) {
        // A backend that ran before and is gone now is an error, not a skip.
        const bool skip = kind == protocol::kBackendUnavailable && !outcome.device;
        outcome.status = skip ? BackendStatus::NotSupported : BackendStatus::Error;
        outcome.message = event.value(protocol::kMessage, "");
        const Verdict verdict = skip ? Verdict::NotSupported : Verdict::Crash;
        for (; next < plan.tasks.size(); ++next)
          record(plan.tasks[next], abnormalResult(plan.tasks[next], verdict, outcome.message));
        stop = true;
        break;
      } else if (kind == protocol::kResult && event.value(protocol::kIndex, -1) == int(next)) {
        record(plan.tasks[next], results::TaskResult::fromJson(event));
        ++next;
        gotResult = true;
      }
    }
    if (stop) break;
  }
  outcome.wallSeconds = std::chrono::duration<double>(Clock::now() - start).count();
  return outcome;
}

}  // namespace runner
