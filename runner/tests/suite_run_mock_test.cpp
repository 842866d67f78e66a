// Whole runs (`lightcts run`'s runSuite, `lightcts merge`) with the mock
// worker in place of `lightcts worker`: retries and flakes, interruption by
// SIGINT and SIGTERM, shards and the merge's refusals, on any machine.
#include "runner/run_merge.h"
#include "runner/suite_run.h"

#include "runner/tests/mock_worker_script.h"

#include <gtest/gtest.h>

#include <csignal>
#include <sstream>

namespace runner {
namespace {

using Json = nlohmann::ordered_json;
namespace fs = std::filesystem;

const char* const kScenes[] = {"point-d-zero", "point-d-half-range", "point-d-range"};

class SuiteRun : public testing::MockWorkerTest {
 protected:
  void SetUp() override {
    MockWorkerTest::SetUp();
    fs::create_directories(dir_ / "scenes" / "attenuation");
    for (const char* scene : kScenes)
      fs::copy_file(fs::path(LIGHTCTS_SOURCE_DIR) / "suite/scenes/attenuation" / (std::string(scene) + ".json"),
                    dir_ / "scenes" / "attenuation" / (std::string(scene) + ".json"));
  }

  RunOptions options(const std::string& out) const {
    RunOptions o;
    o.backends = {"vulkan"};
    o.scenesDir = (dir_ / "scenes").string();
    o.outDir = (dir_ / out).string();
    o.noMutants = true;
    o.noBudgets = true;
    o.jobs = 1;
    o.timeoutSeconds = 20;
    o.referenceCache = (dir_ / "cache").string();
    o.workerExecutable = kMockWorker;
    o.commandLine = "lightcts run (mock worker)";
    return o;
  }

  int run(const RunOptions& o) {
    std::ostringstream out;
    return runSuite(o, out, err_);
  }

  Json results(const std::string& out) const { return Json::parse(std::ifstream(dir_ / out / "results.json")); }

  // name -> verdict of a results.json's tests.
  static std::map<std::string, std::string> verdicts(const Json& results) {
    std::map<std::string, std::string> v;
    for (const Json& t : results["tests"]) v[t["name"]] = t["verdict"];
    return v;
  }

  std::ostringstream err_;
};

TEST_F(SuiteRun, AFailThenAPassIsAFlakeAndARepeatedCrashStaysACrash) {
  script({{"tests",
           {{"attenuation.point-d-half-range.vulkan", {"fail", "pass"}},
            {"attenuation.point-d-range.vulkan", {"crash"}}}}});
  EXPECT_EQ(run(options("out")), 1);
  const Json r = results("out");
  EXPECT_EQ(verdicts(r), (std::map<std::string, std::string>{{"attenuation.point-d-half-range.vulkan", "Flake"},
                                                             {"attenuation.point-d-range.vulkan", "Crash"},
                                                             {"attenuation.point-d-zero.vulkan", "Pass"}}));
  for (const Json& t : r["tests"])
    EXPECT_EQ(t.contains("attempts") ? t["attempts"].size() : 0u, t["verdict"] == "Pass" ? 0u : 2u) << t["name"];
  EXPECT_TRUE(fs::exists(dir_ / "out" / "junit.xml"));
}

// SIGTERM (a CI job's time limit) halfway: the finished test keeps its
// verdict, the rest are NotRun, every output is written, and no retry starts.
TEST_F(SuiteRun, SigtermHalfwayWritesEveryOutputWithTheFinishedTestsAndTheRestNotRun) {
  script({{"tests", {{"attenuation.point-d-range.vulkan", {"interrupt:SIGTERM"}}}}});
  RunOptions o = options("out");
  o.flakeRetries = 1;
  EXPECT_EQ(run(o), 128 + SIGTERM);
  const Json r = results("out");
  EXPECT_EQ(verdicts(r), (std::map<std::string, std::string>{{"attenuation.point-d-half-range.vulkan", "Pass"},
                                                             {"attenuation.point-d-range.vulkan", "NotRun"},
                                                             {"attenuation.point-d-zero.vulkan", "NotRun"}}));
  EXPECT_EQ(r["backends"][0]["counts"]["NotRun"], 2);
  std::stringstream junit;
  junit << std::ifstream(dir_ / "out" / "junit.xml").rdbuf();
  EXPECT_NE(junit.str().find("NotRun: not run: the run was interrupted by SIGTERM"), std::string::npos);
  EXPECT_TRUE(fs::exists(dir_ / "out" / "report" / "index.html"));
  EXPECT_EQ(counted("out/mock-starts.txt", "vulkan"), 1);
  EXPECT_NE(err_.str().find("interrupted by SIGTERM: 1 test(s) finished, 2 NotRun; exit status 143"),
            std::string::npos)
      << err_.str();
}

TEST_F(SuiteRun, SigintExitsWith130) {
  script({{"tests", {{"attenuation.point-d-half-range.vulkan", {"interrupt:SIGINT"}}}}});
  EXPECT_EQ(run(options("out")), 128 + SIGINT);
  EXPECT_EQ(verdicts(results("out"))["attenuation.point-d-zero.vulkan"], "NotRun");
}

// A worker the signal reaches too, or one that never stops writing, is
// stopped with the run and its test is NotRun, not a Crash.
TEST_F(SuiteRun, AWorkerThatDiesOrChattersWithTheSignalLeavesItsTestNotRun) {
  for (const char* event : {"interrupt-and-die:SIGTERM", "interrupt-and-chatter:SIGTERM"}) {
    script({{"tests", {{"attenuation.point-d-range.vulkan", {event}}}}});
    EXPECT_EQ(run(options("out")), 128 + SIGTERM) << event;
    EXPECT_EQ(verdicts(results("out"))["attenuation.point-d-range.vulkan"], "NotRun") << event;
    EXPECT_EQ(verdicts(results("out"))["attenuation.point-d-half-range.vulkan"], "Pass") << event;
  }
}

// A worker someone sent SIGTERM alone crashed: the run, not interrupted,
// goes on (after a moment's wait for a signal that does not come).
TEST_F(SuiteRun, AWorkerSignalledAloneIsACrashAndTheRunGoesOn) {
  script({{"tests", {{"attenuation.point-d-half-range.vulkan", {"signalled:SIGTERM"}}}}});
  RunOptions o = options("out");
  o.flakeRetries = 0;
  EXPECT_EQ(run(o), 1);
  const auto v = verdicts(results("out"));
  EXPECT_EQ(v.at("attenuation.point-d-half-range.vulkan"), "Crash");
  EXPECT_EQ(v.at("attenuation.point-d-zero.vulkan"), "Pass");
}

TEST_F(SuiteRun, ShardsMergeIntoTheWholeRunAndTheMergeRefusesAShardTwice) {
  script(Json::object());
  RunOptions first = options("shard-1"), second = options("shard-2");
  first.shard = ShardSpec{1, 2};
  second.shard = ShardSpec{2, 2};
  EXPECT_EQ(run(first), 0);
  EXPECT_EQ(run(second), 0);
  EXPECT_EQ(results("shard-1")["tests"].size() + results("shard-2")["tests"].size(), 3u);
  std::ostringstream out;
  EXPECT_EQ(mergeRuns({{(dir_ / "shard-1").string(), (dir_ / "shard-2").string()}, (dir_ / "merged").string(), "merge", ""},
                      out),
            0);
  EXPECT_EQ(verdicts(results("merged")).size(), 3u);
  EXPECT_THROW(mergeRuns({{(dir_ / "shard-1").string(), (dir_ / "shard-1").string()}, (dir_ / "twice").string(), "merge", ""}, out),
               MergeRefused);
  EXPECT_THROW(mergeRuns({{(dir_ / "shard-2").string()}, (dir_ / "alone").string(), "merge", ""}, out), MergeRefused);
  EXPECT_FALSE(fs::exists(dir_ / "twice" / "results.json"));
  // A shard's results.json edited by hand, a key missing: refused, naming the key.
  Json edited = results("shard-2");
  edited["tests"][0].erase("verdict");
  std::ofstream(dir_ / "shard-2" / "results.json") << edited.dump(1);
  try {
    mergeRuns({{(dir_ / "shard-1").string(), (dir_ / "shard-2").string()}, (dir_ / "edited").string(), "merge", ""}, out);
    ADD_FAILURE() << "merged a shard without a verdict";
  } catch (const MergeRefused& e) {
    EXPECT_NE(std::string(e.what()).find("shard-2/results.json: tests[0].verdict is missing"), std::string::npos)
        << e.what();
  }
}

TEST_F(SuiteRun, AnInterruptedShardMergesAndItsNotRunTestsFailTheMergedRun) {
  // An interrupted shard is a shard: its NotRun tests merge, and fail the merged run.
  script({{"tests", {{"attenuation.point-d-half-range.vulkan", {"interrupt:SIGINT"}}}}});
  RunOptions first = options("shard-1"), second = options("shard-2");
  first.shard = ShardSpec{1, 2};
  second.shard = ShardSpec{2, 2};
  run(first);
  run(second);
  std::ostringstream out;
  EXPECT_EQ(mergeRuns({{(dir_ / "shard-1").string(), (dir_ / "shard-2").string()}, (dir_ / "merged").string(), "merge", ""},
                      out),
            1);
  const auto v = verdicts(results("merged"));
  EXPECT_EQ(v.size(), 3u);
  EXPECT_EQ(v.at("attenuation.point-d-half-range.vulkan"), "NotRun");
}

}  // namespace
}  // namespace runner
