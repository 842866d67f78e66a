// What `lightcts run` does on SIGINT (Ctrl-C) and SIGTERM (what a CI job's
// time limit sends). The first signal stops the run: each worker is killed,
// the tests it had not finished and those not started are NotRun, and the
// run writes results.json, junit.xml and the report with every finished
// test, then exits with interruptedExitStatus (128 + the signal, as a shell
// reports a process the signal ended). A second signal ends the process at
// once, killing the workers first and writing nothing more.
#pragma once

#include <chrono>

namespace runner {

// While one lives, SIGINT and SIGTERM are the run's (unless the process was
// started ignoring one: it stays ignored); the handlers before it come back
// when it goes. One at a time: a second throws std::logic_error.
class InterruptionGuard {
 public:
  InterruptionGuard();
  ~InterruptionGuard();
  InterruptionGuard(const InterruptionGuard&) = delete;
  InterruptionGuard& operator=(const InterruptionGuard&) = delete;
};

// The signal that interrupted the run; 0 while none has (or without a guard).
int interruptingSignal();
// Whether the run is interrupted, waiting up to `grace` for a signal to
// reach it: a worker that SIGINT or SIGTERM ended was likely sent it with
// the run (`pkill`, a container's stop), and can be seen to end first.
bool runInterrupted(std::chrono::milliseconds grace = std::chrono::milliseconds(0));
// Readable once the run is interrupted, and from then on: what a thread
// waiting on a worker's output polls beside it. -1 without a guard.
int interruptionDescriptor();

// The worker process groups a second signal kills before the process ends
// (runner/worker_process.h keeps this up to date).
void addWorkerGroup(int pid);
void removeWorkerGroup(int pid);

// 128 + signal: 130 for SIGINT, 143 for SIGTERM.
int interruptedExitStatus(int signal);
// "SIGINT", "SIGTERM".
const char* signalName(int signal);

}  // namespace runner
