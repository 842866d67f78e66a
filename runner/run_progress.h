// What `lightcts run` prints while it runs: per combination, tests
// done of total, failures so far, elapsed time and an estimate of the time
// left. On a terminal the lines are redrawn in place (one per combination);
// otherwise each combination prints a plain line at every tenth of its tests
// and when it is done, so a CI log shows progress without a wall of lines.
// Thread-safe: the threads that read the workers call it concurrently, and
// every other line the run prints goes through note().
#pragma once

#include <chrono>
#include <mutex>
#include <ostream>
#include <string>
#include <vector>

namespace runner {

class RunProgress {
 public:
  // `totals`: each combination's task count, in run order; `names` their suffixes.
  RunProgress(std::ostream& out, bool terminal, std::vector<std::string> names, std::vector<std::size_t> totals);
  ~RunProgress();
  RunProgress(const RunProgress&) = delete;
  RunProgress& operator=(const RunProgress&) = delete;

  // A task of `combination` finished; `failed` when it counts as a failure.
  void taskDone(std::size_t combination, bool failed);
  // Tasks that will not run (a backend that is not present): done, not failed.
  void tasksSkipped(std::size_t combination, std::size_t count);
  // A line of its own (a Crash, a Timeout, a retry), printed above the progress lines.
  void note(const std::string& line);
  // Leaves the progress lines as they are and prints nothing more.
  void finish();

  // The line of one combination: "vulkan: 120/4862 tests, 0 failed, 12 s, about 3 min left".
  std::string line(std::size_t combination) const;

 private:
  using Clock = std::chrono::steady_clock;
  struct Combination {
    std::string name;
    std::size_t total = 0, done = 0, failed = 0;
    int printedTenths = -1;  // the last tenth printed as a plain line
    bool started = false;
    Clock::time_point start;
  };
  void advance(std::size_t combination, std::size_t count, bool failed);
  void redraw();  // terminal: every combination's line, in place
  void erase();   // terminal: moves up over the lines drawn last

  std::ostream& out_;
  const bool terminal_;
  std::vector<Combination> combinations_;
  std::size_t drawnLines_ = 0;
  Clock::time_point lastDraw_{};
  bool finished_ = false;
  mutable std::mutex mutex_;
};

}  // namespace runner
