// A timed-out worker is killed with its whole process group: a process it
// started must not outlive it.
#include "runner/worker_process.h"

#include "runner/tests/process_ended.h"

#include <gtest/gtest.h>

#include <csignal>
#include <fstream>
#include <string>

namespace runner {
namespace {

TEST(WorkerProcess, KillEndsTheWorkersWholeProcessGroup) {
  std::string line;
  int grandchild = -1;
  {
    WorkerProcess worker({"/bin/sh", "-c", "sleep 300 & echo $!; wait"}, "/dev/null");
    ASSERT_EQ(worker.readLine(std::chrono::seconds(10), line), WorkerProcess::ReadStatus::Line);
    grandchild = std::stoi(line);
    ASSERT_FALSE(testing::endedOrZombie(grandchild));
    EXPECT_EQ(worker.readLine(std::chrono::milliseconds(100), line), WorkerProcess::ReadStatus::TimedOut);
    worker.finish(true);
  }
  const bool ended = testing::endsSoon(grandchild);
  if (!ended) ::kill(grandchild, SIGKILL);  // leave nothing behind
  EXPECT_TRUE(ended) << "the worker's child " << grandchild << " outlived the killed worker";
}

}  // namespace
}  // namespace runner
