// Runs one WorkerPlan (a part of a combination, or a retry) in as many worker
// processes as it takes: a worker that dies or hangs costs its current test
// (Crash or Timeout) and a new worker picks up at the next one. A worker
// that dies or hangs before its backend is up would do the same for every
// task: the backend is an error and the rest of the plan is not run. Once
// the run is interrupted (runner/run_interruption.h) the worker is killed
// and every task it had not finished is NotRun.
#pragma once

#include "comparison/run_status.h"
#include "results/run_records.h"
#include "runner/worker_plan.h"

#include <chrono>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace runner {

struct PartOutcome {
  comparison::BackendStatus status = comparison::BackendStatus::Ran;
  std::string message;
  std::optional<results::DeviceRecord> device;  // what the worker said of its device
  std::vector<results::TaskResult> results;  // one per task, in plan order
  double wallSeconds = 0;
};

struct PartCallbacks {
  std::function<void(const WorkerTask&, const results::TaskResult& result)> taskDone;
  std::function<void(const std::string& line)> note;  // a Crash or Timeout, for the console
  std::function<void()> backendUp;  // the first worker's backend came up (runner/part_scheduler.h)
};

// The plan goes to logsDir/<fileStem>.plan.json and the workers' stderr to
// logsDir/<fileStem>.log (replaced: an earlier run's lines are not this run's).
PartOutcome runPart(const WorkerPlan& plan, const std::string& workerExecutable, std::chrono::milliseconds timeout,
                    const std::filesystem::path& logsDir, const std::string& fileStem, const PartCallbacks& callbacks);

}  // namespace runner
