// A timed-out worker is killed with its whole process group: a process it
// started must not outlive it.
#include "runner/worker_process.h"

#include <gtest/gtest.h>

#include <csignal>
#include <fstream>
#include <string>
#include <thread>

namespace runner {
namespace {

// True when `pid` is gone or a zombie (killed, not yet reaped by init).
bool endedOrZombie(int pid) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string text;
  if (!std::getline(stat, text)) return true;
  const std::size_t close = text.rfind(')');
  return close == std::string::npos || text.size() < close + 3 || text[close + 2] == 'Z' || text[close + 2] == 'X';
}

TEST(WorkerProcess, KillEndsTheWorkersWholeProcessGroup) {
  std::string line;
  int grandchild = -1;
  {
    WorkerProcess worker({"/bin/sh", "-c", "sleep 300 & echo $!; wait"}, "/dev/null");
    ASSERT_EQ(worker.readLine(std::chrono::seconds(10), line), WorkerProcess::ReadStatus::Line);
    grandchild = std::stoi(line);
    ASSERT_FALSE(endedOrZombie(grandchild));
    EXPECT_EQ(worker.readLine(std::chrono::milliseconds(100), line), WorkerProcess::ReadStatus::TimedOut);
    worker.finish(true);
  }
  bool ended = false;
  for (int i = 0; i < 50 && !ended; ++i) {
    ended = endedOrZombie(grandchild);
    if (!ended) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  if (!ended) ::kill(grandchild, SIGKILL);  // leave nothing behind
  EXPECT_TRUE(ended) << "the worker's child " << grandchild << " outlived the killed worker";
}

}  // namespace
}  // namespace runner
