// The worker side of `lightcts run` (the hidden `lightcts worker` command):
// runs the tasks of a WorkerPlan from `start` on, one backend at a time, and
// writes one JSON line per event on `out` (runner/worker_protocol.h),
// flushed at once, so the runner knows how far a worker got when it crashes
// or hangs.
//
// A DriverError during a test is reported as that test's Crash, and the
// worker then exits (status 4) rather than keep using a device in an unknown
// state; the runner starts a new worker at the next test.
#pragma once

#include "runner/worker_plan.h"

#include <ostream>

namespace runner {

// Returns the process exit status.
int runWorker(const WorkerPlan& plan, int start, std::ostream& out);

}  // namespace runner
