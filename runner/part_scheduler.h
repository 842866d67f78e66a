// Runs the worker parts of a run (runner/run_plan.h) on up to `jobs` threads,
// each of which waits on one worker process at a time. A combination's
// first part runs before its others are released, and they are released as
// soon as its backend is up: when it never comes up (the driver is missing
// or broken), the others are not started but skipped with that part's
// verdict, which is what they would have found, whatever --jobs is.
#pragma once

#include "runner/run_plan.h"

#include <cstddef>
#include <functional>
#include <vector>

namespace runner {

// `run(p, backendUp)` runs part p and calls backendUp() once its backend is
// up; `skip(p, first)` records part p as skipped because part `first`
// (the combination's first) never got its backend up. With `skip` null,
// every part is independent and runs. Exceptions thrown by `run` or `skip`
// are rethrown once every thread has stopped.
void runPartsInParallel(const std::vector<WorkerPart>& parts, int jobs,
                        const std::function<void(std::size_t part, const std::function<void()>& backendUp)>& run,
                        const std::function<void(std::size_t part, std::size_t firstPart)>& skip);

}  // namespace runner
