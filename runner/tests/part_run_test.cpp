// One worker part against the mock worker (no driver): a crash or hang costs
// its test and a fresh worker goes on; a worker that never brings its
// backend up costs the part; lines that are no protocol object are skipped.
#include "runner/part_run.h"

#include "runner/tests/mock_worker_script.h"

#include <gtest/gtest.h>

namespace runner {
namespace {

using comparison::BackendStatus;
using comparison::Verdict;
using Json = nlohmann::ordered_json;

class PartRun : public testing::MockWorkerTest {
 protected:
  PartOutcome run(std::chrono::milliseconds timeout = std::chrono::seconds(20)) {
    WorkerPlan plan;
    plan.combination = {"vulkan", "vulkan", ""};
    plan.outDir = dir_.string();
    for (const char* test : {"g.a.vulkan", "g.b.vulkan", "g.c.vulkan"}) plan.tasks.push_back({test, "unused.json"});
    return runPart(plan, kMockWorker, timeout, dir_, "part", {});
  }

  static std::vector<Verdict> verdicts(const PartOutcome& outcome) {
    std::vector<Verdict> v;
    for (const results::TaskResult& r : outcome.results) v.push_back(r.rawVerdict);
    return v;
  }
};

TEST_F(PartRun, EveryTaskGetsItsWorkersResultInPlanOrder) {
  script({{"devices", {{"vulkan", {{"name", "mock gpu"}}}}}});
  const PartOutcome outcome = run();
  EXPECT_EQ(outcome.status, BackendStatus::Ran);
  ASSERT_TRUE(outcome.device.has_value());
  EXPECT_EQ(outcome.device->name, "mock gpu");
  EXPECT_EQ(verdicts(outcome), (std::vector<Verdict>{Verdict::Pass, Verdict::Pass, Verdict::Pass}));
  EXPECT_EQ(outcome.results[1].test, "g.b.vulkan");
  ASSERT_TRUE(outcome.results[1].timingsMs.has_value());
  EXPECT_EQ(outcome.results[1].timingsMs->total, 6.0);
  EXPECT_EQ(counted("mock-starts.txt", "vulkan"), 1);
}

TEST_F(PartRun, ACrashCostsItsTestAndAFreshWorkerTakesTheNext) {
  script({{"tests", {{"g.b.vulkan", {"crash"}}}}});
  const PartOutcome outcome = run();
  EXPECT_EQ(outcome.status, BackendStatus::Ran);
  EXPECT_EQ(verdicts(outcome), (std::vector<Verdict>{Verdict::Pass, Verdict::Crash, Verdict::Pass}));
  EXPECT_NE(outcome.results[1].message.find("killed by signal SIGKILL"), std::string::npos) << outcome.results[1].message;
  EXPECT_FALSE(outcome.results[1].timingsMs.has_value());
  EXPECT_EQ(counted("mock-starts.txt", "vulkan"), 2);
}

TEST_F(PartRun, AHangTimesOutItsTestAndAFreshWorkerTakesTheNext) {
  script({{"tests", {{"g.a.vulkan", {"hang"}}}}});
  const PartOutcome outcome = run(std::chrono::milliseconds(300));
  EXPECT_EQ(verdicts(outcome), (std::vector<Verdict>{Verdict::Timeout, Verdict::Pass, Verdict::Pass}));
  EXPECT_NE(outcome.results[0].message.find("no result within 0.3"), std::string::npos) << outcome.results[0].message;
  EXPECT_EQ(counted("mock-starts.txt", "vulkan"), 2);
}

TEST_F(PartRun, LinesThatAreNoProtocolObjectAndResultsOutOfTurnAreSkipped) {
  script({{"tests", {{"g.a.vulkan", {"garbage"}}, {"g.c.vulkan", {"fail"}}}}});
  const PartOutcome outcome = run();
  EXPECT_EQ(verdicts(outcome), (std::vector<Verdict>{Verdict::Pass, Verdict::Pass, Verdict::Fail}));
  EXPECT_EQ(outcome.results[1].test, "g.b.vulkan");
  EXPECT_EQ(counted("mock-starts.txt", "vulkan"), 1);
}

TEST_F(PartRun, ADriverErrorAfterAResultLosesNoTest) {
  script({{"tests", {{"g.a.vulkan", {"pass-then-exit-4"}}}}});
  const PartOutcome outcome = run();
  EXPECT_EQ(verdicts(outcome), (std::vector<Verdict>{Verdict::Pass, Verdict::Pass, Verdict::Pass}));
  EXPECT_EQ(counted("mock-starts.txt", "vulkan"), 2);
}

TEST_F(PartRun, ASlowStartWithinTheTimeoutIsNoTimeout) {
  script({{"start", "slow:200"}});
  EXPECT_EQ(verdicts(run(std::chrono::seconds(5))),
            (std::vector<Verdict>{Verdict::Pass, Verdict::Pass, Verdict::Pass}));
}

TEST_F(PartRun, AWorkerThatDiesBeforeItsBackendIsUpCostsThePart) {
  script({{"start", "crash"}});
  const PartOutcome outcome = run();
  EXPECT_EQ(outcome.status, BackendStatus::Error);
  EXPECT_NE(outcome.message.find("the worker ended before its backend was up"), std::string::npos) << outcome.message;
  EXPECT_EQ(verdicts(outcome), (std::vector<Verdict>{Verdict::Crash, Verdict::Crash, Verdict::Crash}));
  EXPECT_EQ(counted("mock-starts.txt", "vulkan"), 1);  // not one worker per task
}

TEST_F(PartRun, AWorkerThatHangsBeforeItsBackendIsUpCostsThePart) {
  script({{"start", "hang"}});
  const PartOutcome outcome = run(std::chrono::milliseconds(300));
  EXPECT_EQ(outcome.status, BackendStatus::Error);
  EXPECT_NE(outcome.message.find("did not start within the timeout"), std::string::npos) << outcome.message;
  EXPECT_EQ(verdicts(outcome), (std::vector<Verdict>{Verdict::Timeout, Verdict::Timeout, Verdict::Timeout}));
}

TEST_F(PartRun, AnAbsentBackendIsNotSupportedForEveryTask) {
  script({{"start", "absent"}});
  const PartOutcome outcome = run();
  EXPECT_EQ(outcome.status, BackendStatus::NotSupported);
  EXPECT_EQ(outcome.message, "mock: no such driver here");
  EXPECT_EQ(verdicts(outcome),
            (std::vector<Verdict>{Verdict::NotSupported, Verdict::NotSupported, Verdict::NotSupported}));
}

TEST_F(PartRun, ABackendErrorAfterTheBackendWasUpIsAnErrorAndNoSkip) {
  script({{"tests", {{"g.b.vulkan", {"backend-error"}}}}});
  const PartOutcome outcome = run();
  EXPECT_EQ(outcome.status, BackendStatus::Error);
  EXPECT_EQ(verdicts(outcome), (std::vector<Verdict>{Verdict::Pass, Verdict::Crash, Verdict::Crash}));
}

}  // namespace
}  // namespace runner
