#include "runner/worker_process.h"

#include "runner/run_interruption.h"

#include <cerrno>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <poll.h>
#include <stdexcept>
#include <sys/wait.h>
#include <unistd.h>

namespace runner {
namespace {

std::string systemError(const std::string& what) { return what + ": " + std::strerror(errno); }

}  // namespace

WorkerProcess::WorkerProcess(const std::vector<std::string>& argv, const std::string& stderrFile) {
  int pipeFds[2];
  if (pipe2(pipeFds, O_CLOEXEC) != 0) throw std::runtime_error(systemError("cannot create a pipe"));
  const int errFd = open(stderrFile.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (errFd < 0) {
    close(pipeFds[0]);
    close(pipeFds[1]);
    throw std::runtime_error(systemError("cannot open " + stderrFile));
  }
  // Built before fork: the child may only call async-signal-safe functions.
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);

  const pid_t pid = fork();
  if (pid < 0) {
    close(pipeFds[0]);
    close(pipeFds[1]);
    close(errFd);
    throw std::runtime_error(systemError("cannot start a worker"));
  }
  if (pid == 0) {
    setpgid(0, 0);  // its own process group: a kill reaches whatever the worker started
    dup2(pipeFds[1], STDOUT_FILENO);
    dup2(errFd, STDERR_FILENO);
    execv(args[0], args.data());
    _exit(127);
  }
  setpgid(pid, pid);  // also here, so that a kill right after the start finds the group
  addWorkerGroup(pid);
  close(pipeFds[1]);
  close(errFd);
  pid_ = pid;
  fd_ = pipeFds[0];
}

WorkerProcess::~WorkerProcess() {
  if (pid_ > 0) finish(true);
  if (fd_ >= 0) close(fd_);
}

WorkerProcess::ReadStatus WorkerProcess::readLine(std::chrono::milliseconds timeout, std::string& line) {
  auto deadline = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    if (const auto newline = buffer_.find('\n'); newline != std::string::npos) {
      line = buffer_.substr(0, newline);
      buffer_.erase(0, newline + 1);
      return ReadStatus::Line;
    }
    if (fd_ < 0) return interrupted_ ? ReadStatus::Interrupted : ReadStatus::Closed;
    // Interrupted: the worker's group is killed at once, and what it wrote
    // before is still read (a result that arrived with the signal is kept),
    // up to its end of output, which the kill brings within a moment.
    if (!interrupted_ && interruptingSignal() != 0) {
      interrupted_ = true;
      if (pid_ > 0) ::kill(-pid_, SIGKILL);
      deadline = std::chrono::steady_clock::now() + kDrainAfterInterruption;
    }
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) return interrupted_ ? ReadStatus::Interrupted : ReadStatus::TimedOut;
    // The interruption's descriptor (-1 without a guard, which poll skips)
    // wakes every thread that waits on a worker.
    pollfd p[2] = {{fd_, POLLIN, 0}, {interrupted_ ? -1 : interruptionDescriptor(), POLLIN, 0}};
    const int ready = poll(p, 2, int(left.count()));
    if (ready < 0 && errno == EINTR) continue;
    if (ready < 0) throw std::runtime_error(systemError("cannot wait for a worker"));
    if (ready == 0) return interrupted_ ? ReadStatus::Interrupted : ReadStatus::TimedOut;
    if (p[0].revents == 0) continue;  // the interruption woke it: the next turn kills the worker
    char chunk[65536];
    const ssize_t n = read(fd_, chunk, sizeof chunk);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      close(fd_);
      fd_ = -1;
      // A last line without '\n' is still a line.
      if (!buffer_.empty()) {
        line.swap(buffer_);
        buffer_.clear();
        return ReadStatus::Line;
      }
      return interrupted_ ? ReadStatus::Interrupted : ReadStatus::Closed;
    }
    buffer_.append(chunk, std::size_t(n));
  }
}

std::string WorkerProcess::finish(bool kill) {
  if (pid_ <= 0) return "already finished";
  // The whole group: a timed-out worker's own children (a driver's helper
  // processes, a shell) must not outlive it.
  if (kill) ::kill(-pid_, SIGKILL);
  // Forgotten before it is reaped: until then its pid cannot name another
  // process, which a second signal would kill.
  removeWorkerGroup(pid_);
  int status = 0;
  while (waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
  }
  pid_ = -1;
  if (WIFEXITED(status)) {
    exitStatus_ = WEXITSTATUS(status);
    return "exit status " + std::to_string(exitStatus_);
  }
  if (WIFSIGNALED(status)) {
    const int sig = WTERMSIG(status);
    endingSignal_ = sig;
    const char* name = sigabbrev_np(sig);
    return std::string("killed by signal ") + (name ? std::string("SIG") + name : "?") + " (" + std::to_string(sig) +
           ")";
  }
  return "ended";
}

}  // namespace runner
