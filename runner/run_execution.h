// The third step of `lightcts run`: the units' tasks in worker processes,
// every combination's parts up to --jobs at once (runner/part_scheduler.h),
// then flake detection: the model's tests that failed, crashed or timed out
// (and not as their expected-failures line says) again in fresh workers, up
// to --flake-retries times.
#pragma once

#include "results/result_rules.h"
#include "runner/run_inputs.h"
#include "runner/run_units.h"

#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

namespace runner {

// One attempt at a task: the worker's result, and the log of that worker.
struct Attempt {
  results::TaskResult result;
  std::string log;  // relative to --out: logs/<suffix>.log, logs/<suffix>.retry-N.log
};

// What a combination's workers said: its status over its parts (the device
// of the first part that has one), and every task's attempts, in part order.
struct CombinationRun {
  results::StatusAndMessage status;
  std::optional<results::DeviceRecord> device;
  std::vector<WorkerTask> tasks;
  std::vector<std::vector<Attempt>> attempts;  // per task: the first, then each retry
  double workerSeconds = 0;    // the parts' and retries' worker time, summed (parts may overlap)
  results::TaskTimes taskTimes;  // the first attempts' stage times
};

// Where the workers write and what they share.
struct WorkerSetting {
  std::filesystem::path outDir;
  std::filesystem::path referenceCache;
};

// One CombinationRun per combination of the inputs (one without tasks in
// this shard has none). Writes logs/<suffix>.log (every part's log under a
// line naming it) and the retries' logs; prints progress on `out`.
std::vector<CombinationRun> executeRun(const RunOptions& options, const RunInputs& inputs, const RunUnits& plan,
                                       const WorkerSetting& setting, std::ostream& out);

}  // namespace runner
