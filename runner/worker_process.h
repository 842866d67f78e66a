// A child process whose standard output the runner reads line by line with a
// deadline (the per-test timeout), and which it can kill. Owning the pid and
// the pipe, it kills and reaps the child when destroyed, so no worker
// outlives the run, also on an error path.
#pragma once

#include <chrono>
#include <optional>
#include <string>
#include <vector>

namespace runner {

class WorkerProcess {
 public:
  // Starts `argv` (argv[0] is the executable's path) in a process group of
  // its own, with stdout on a pipe and stderr appended to `stderrFile`. Throws std::runtime_error when the
  // process cannot start.
  WorkerProcess(const std::vector<std::string>& argv, const std::string& stderrFile);
  ~WorkerProcess();
  WorkerProcess(const WorkerProcess&) = delete;
  WorkerProcess& operator=(const WorkerProcess&) = delete;

  enum class ReadStatus { Line, Closed, TimedOut, Interrupted };
  // The next line (without '\n') within `timeout`; Closed when the child
  // closed its output (it exited or died); Interrupted once the run is
  // (runner/run_interruption.h): the child is killed then, and every whole
  // line it had written is still returned first.
  ReadStatus readLine(std::chrono::milliseconds timeout, std::string& line);

  // Waits for the child to end and describes how: "exit status N" or
  // "killed by signal SIGSEGV (11)". Kills it first, with its whole process
  // group, when `kill` is true.
  std::string finish(bool kill);
  int exitStatus() const { return exitStatus_; }  // after finish(); -1 when killed by a signal
  int endingSignal() const { return endingSignal_; }  // after finish(): the signal that ended it, or 0

 private:
  int pid_ = -1;
  int fd_ = -1;
  int exitStatus_ = -1;
  int endingSignal_ = 0;
  bool interrupted_ = false;  // the run was interrupted and the worker killed
  std::string buffer_;
  // How long what an interrupted worker wrote is still read: its group is
  // killed first, so its output ends at once unless a process left the group.
  static constexpr std::chrono::milliseconds kDrainAfterInterruption{2000};
};

}  // namespace runner
