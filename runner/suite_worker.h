// The worker side of `lightcts run` (the hidden `lightcts worker` command):
// runs the tasks of a WorkerPlan from `start` on, one backend at a time, and
// writes one JSON line per event on `out`, flushed at once, so the runner
// knows how far a worker got when it crashes or hangs:
//
//   {"kind": "device", "device": {...}}                    a backend is up
//   {"kind": "backend_unavailable", "message": "..."}      NotSupported: the run skips the rest
//   {"kind": "backend_error", "message": "..."}            creating it failed (driver error,
//                                                          --expect-driver mismatch)
//   {"kind": "result", "index": k, "raw_verdict": ..., "metrics": ..., ...}
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
