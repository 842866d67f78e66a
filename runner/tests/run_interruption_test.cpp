// The signal handling itself, with signals raised in this process (raise()
// runs the handler before it returns, so the order is certain): the first
// signal is noted and wakes a wait on a worker; a second kills the workers'
// process groups and ends the process at once.
#include "runner/run_interruption.h"

#include "runner/worker_process.h"
#include "runner/tests/process_ended.h"

#include <gtest/gtest.h>

#include <csignal>
#include <fstream>
#include <thread>
#include <unistd.h>

namespace runner {
namespace {

TEST(RunInterruption, AFirstSignalIsNotedAndEndsAWaitOnAWorker) {
  const InterruptionGuard guard;
  EXPECT_EQ(interruptingSignal(), 0);
  WorkerProcess worker({"/bin/sh", "-c", "echo up; exec sleep 300"}, "/dev/null");
  std::string line;
  ASSERT_EQ(worker.readLine(std::chrono::seconds(10), line), WorkerProcess::ReadStatus::Line);
  std::thread signaller([] { std::raise(SIGTERM); });  // another thread's signal wakes this one's wait
  const auto started = std::chrono::steady_clock::now();
  EXPECT_EQ(worker.readLine(std::chrono::seconds(60), line), WorkerProcess::ReadStatus::Interrupted);
  signaller.join();
  EXPECT_LT(std::chrono::steady_clock::now() - started, std::chrono::seconds(30));
  EXPECT_EQ(interruptingSignal(), SIGTERM);
  EXPECT_EQ(interruptedExitStatus(SIGTERM), 143);
  EXPECT_EQ(interruptedExitStatus(SIGINT), 130);
}

TEST(RunInterruption, TheGuardGivesTheSignalsBackAndForgetsTheInterruption) {
  struct sigaction before {};
  sigaction(SIGINT, nullptr, &before);
  {
    const InterruptionGuard guard;
    EXPECT_THROW(InterruptionGuard(), std::logic_error);
    std::raise(SIGINT);
    EXPECT_EQ(interruptingSignal(), SIGINT);
  }
  struct sigaction after {};
  sigaction(SIGINT, nullptr, &after);
  EXPECT_EQ(after.sa_handler, before.sa_handler);
  EXPECT_EQ(interruptingSignal(), 0);
  EXPECT_EQ(interruptionDescriptor(), -1);
}

// `lightcts run &` from a script starts ignoring SIGINT: it stays ignored.
TEST(RunInterruption, ASignalIgnoredAtTheStartStaysIgnored) {
  struct sigaction ignore {}, before {};
  ignore.sa_handler = SIG_IGN;
  sigemptyset(&ignore.sa_mask);
  sigaction(SIGINT, &ignore, &before);
  {
    const InterruptionGuard guard;
    std::raise(SIGINT);
    EXPECT_EQ(interruptingSignal(), 0);
  }
  sigaction(SIGINT, &before, nullptr);
}

TEST(RunInterruption, ASecondSignalKillsTheWorkersAndEndsTheProcessAtOnce) {
  const std::string pidFile = ::testing::TempDir() + "lightcts-interruption-" + std::to_string(getpid());
  std::remove(pidFile.c_str());
  EXPECT_EXIT(
      {
        const InterruptionGuard guard;
        WorkerProcess worker({"/bin/sh", "-c", "echo $$ > " + pidFile + "; echo up; exec sleep 300"}, "/dev/null");
        std::string line;
        if (worker.readLine(std::chrono::seconds(10), line) != WorkerProcess::ReadStatus::Line) _exit(1);
        std::raise(SIGTERM);
        std::raise(SIGINT);
        _exit(0);  // not reached: the second signal ended the process
      },
      ::testing::ExitedWithCode(128 + SIGINT), "second signal: ended at once");
  std::ifstream in(pidFile);
  int worker = -1;
  ASSERT_TRUE(in >> worker);
  const bool ended = testing::endsSoon(worker);
  if (!ended) ::kill(worker, SIGKILL);
  EXPECT_TRUE(ended) << "the worker " << worker << " outlived the second signal";
  std::remove(pidFile.c_str());
}

}  // namespace
}  // namespace runner
