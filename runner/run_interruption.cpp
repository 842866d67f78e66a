#include "runner/run_interruption.h"

#include "app/exit_status.h"

#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <poll.h>
#include <stdexcept>
#include <string>
#include <unistd.h>
#include <utility>

namespace runner {
namespace {

// What the handler touches: lock-free atomics and plain descriptors, all it
// may use (POSIX's async-signal-safe functions: write, kill, _exit).
std::atomic<int> interruptingSignal_{0};
std::atomic<bool> guarded_{false};
int wakeRead_ = -1;
int wakeWrite_ = -1;
// One worker per thread at a time: room for --jobs up to this many.
std::array<std::atomic<int>, 4096> workerGroups_{};
struct sigaction previousInt_ {};
struct sigaction previousTerm_ {};

void say(const char* text) { [[maybe_unused]] const ssize_t n = write(STDERR_FILENO, text, std::strlen(text)); }

extern "C" void onInterrupt(int signal) {
  const int savedErrno = errno;  // the thread the signal broke in may be about to read errno
  int none = 0;
  if (interruptingSignal_.compare_exchange_strong(none, signal)) {
    say(signal == SIGINT ? "\nlightcts: run: SIGINT: stopping the workers and writing the finished tests' results "
                           "(a second signal ends at once)\n"
                         : "\nlightcts: run: SIGTERM: stopping the workers and writing the finished tests' results "
                           "(a second signal ends at once)\n");
    const char byte = 1;
    [[maybe_unused]] const ssize_t n = write(wakeWrite_, &byte, 1);
    errno = savedErrno;
    return;
  }
  for (std::atomic<int>& group : workerGroups_)
    if (const int pid = group.load(); pid > 0) kill(-pid, SIGKILL);
  say("lightcts: run: second signal: ended at once\n");
  _exit(interruptedExitStatus(signal));
}

}  // namespace

InterruptionGuard::InterruptionGuard() {
  if (guarded_.exchange(true)) throw std::logic_error("InterruptionGuard: one is alive already");
  int fds[2];
  if (pipe2(fds, O_CLOEXEC | O_NONBLOCK) != 0) {
    guarded_ = false;
    throw std::runtime_error(std::string("cannot create a pipe: ") + std::strerror(errno));
  }
  wakeRead_ = fds[0];
  wakeWrite_ = fds[1];
  interruptingSignal_ = 0;
  struct sigaction action {};
  action.sa_handler = onInterrupt;
  sigemptyset(&action.sa_mask);
  action.sa_flags = 0;  // no SA_RESTART: a wait the signal breaks returns EINTR and looks again
  // A signal the run was started ignoring (`lightcts run &` from a script
  // ignores SIGINT) stays ignored: whoever started it chose so.
  for (const auto& [signal, previous] : {std::pair{SIGINT, &previousInt_}, std::pair{SIGTERM, &previousTerm_}}) {
    sigaction(signal, nullptr, previous);
    if (previous->sa_handler != SIG_IGN) sigaction(signal, &action, nullptr);
  }
}

InterruptionGuard::~InterruptionGuard() {
  sigaction(SIGINT, &previousInt_, nullptr);
  sigaction(SIGTERM, &previousTerm_, nullptr);
  close(wakeRead_);
  close(wakeWrite_);
  wakeRead_ = wakeWrite_ = -1;
  interruptingSignal_ = 0;
  guarded_ = false;
}

int interruptingSignal() { return interruptingSignal_.load(); }

bool runInterrupted(std::chrono::milliseconds grace) {
  if (interruptingSignal() != 0 || !guarded_ || grace.count() <= 0) return interruptingSignal() != 0;
  const auto deadline = std::chrono::steady_clock::now() + grace;
  for (;;) {  // the wake pipe turns readable when the handler has run
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    pollfd wake{wakeRead_, POLLIN, 0};
    if (left.count() <= 0 || poll(&wake, 1, int(left.count())) >= 0 || errno != EINTR)
      return interruptingSignal() != 0;
  }
}

int interruptionDescriptor() { return wakeRead_; }

void addWorkerGroup(int pid) {
  for (std::atomic<int>& group : workerGroups_) {
    int empty = 0;
    if (group.compare_exchange_strong(empty, pid)) return;
  }
}

void removeWorkerGroup(int pid) {
  for (std::atomic<int>& group : workerGroups_) {
    int held = pid;
    if (group.compare_exchange_strong(held, 0)) return;
  }
}

int interruptedExitStatus(int signal) { return app::kExitInterruptedBase + signal; }

const char* signalName(int signal) {
  return signal == SIGINT ? "SIGINT" : signal == SIGTERM ? "SIGTERM" : "a signal";
}

}  // namespace runner
