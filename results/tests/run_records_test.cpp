// results.json's records: each reads back what it writes, and the run
// record writes docs/results-format.md's keys in its order.
#include "results/run_records.h"

#include <gtest/gtest.h>

namespace results {
namespace {

using comparison::Verdict;

RunRecord sampleRun() {
  RunRecord run;
  run.lightctsRevision = "abc123";
  run.scenesDir = "suite/scenes";
  run.mutantsRun = {"unsquared-range"};
  run.mutantCheck = "killers";
  run.jobs = 2;
  run.evidenceLimit = 50;
  TestRecord t;
  t.name = "attenuation.a.vulkan";
  t.group = "attenuation";
  t.scene = "a";
  t.backend = "vulkan";
  t.verdict = Verdict::Flake;
  t.rawVerdict = Verdict::Fail;
  t.metrics = Metrics{};
  t.metrics->tightness = 1.5;
  t.metrics->maxAbsError = std::nullopt;  // not finite: null
  t.metrics->worst.push_back({3, 4, {0.5, std::nullopt, 1.0}, {0.25, 0.25, 0.25}, {0.01, 0.01, 0.01}, 2});
  t.metrics->caught = CaughtBrightness{4.2e-5, std::nullopt};
  t.frames = std::vector<FrameRecord>{{0, Verdict::Fail, 37, 0.25, 812.5, std::nullopt, std::nullopt},
                                      {1, Verdict::Pass, 0, 0.0, 0.1, 0.2, 0.05}};
  t.poppingScore = 0.05;
  t.evidence = EvidenceRecord::inFolder("evidence/attenuation.a.vulkan", 0);
  t.timingsMs = StageTimes{2.0, 3.0, 4.0, 1.0, 1.0, 12.0};
  t.attempts = {{Verdict::Fail, "past tolerance", "logs/vulkan.log"}, {Verdict::Pass, "", "logs/vulkan.retry-1.log"}};
  run.tests.push_back(t);
  BackendRecord b;
  b.backend = "vulkan";
  b.status = comparison::BackendStatus::Ran;
  b.counts = {{Verdict::Flake, 1}};
  b.mutantCounts = {1, 0, 0};
  b.taskTimes = {2, 3.5, 20.0};
  b.device = DeviceRecord{"llvmpipe", "llvmpipe", "Mesa 22.3.6", "1.3.230", "default", 8, 8};
  run.backends.push_back(b);
  run.machine = {"ci-1", "a CPU", 2, "Debian GNU/Linux 12 (bookworm)"};
  run.selection = {{"attenuation.*"}, {"*softpipe*"}, {"vendor.txt"}};
  run.baselineFiles = {{"caselist", "vendor.txt", "abc"}};
  run.mutantsNotChecked = {{"shadow-fade-ignored", "none of its killers is selected"}};
  run.shard = ShardRecord{1, 2, "digest", "test count", "", 10, 5, 9};
  SceneBudgetRecord cut;
  cut.scene = "per-object.eleven-lights";
  cut.cuts = true;
  cut.frames = {{0, 2462, 12.38, 2621.98, 1.0, std::nullopt, std::nullopt}};
  cut.reachImage = "budgets/per-object.eleven-lights/reach.png";
  cut.lightsNotKept = {{0, "p0", 1918, 0, 0, 1918, 1918, 0}};
  SceneBudgetRecord failed;
  failed.scene = "some.scene";
  failed.error = "why";
  run.budgets = {cut, failed};
  MutantRecord m;
  m.mutant = "unsquared-range";
  m.backend = "vulkan";
  m.status = comparison::MutantStatus::Killed;
  m.killers = {"attenuation.a"};
  m.killedBy = {"attenuation.a"};
  m.evidence = EvidenceRecord::inFolder("mutants/unsquared-range.vulkan", 0);
  m.evidence->test = "attenuation.a.vulkan";
  run.mutants.push_back(m);
  return run;
}

TEST(RunRecords, ARunReadsBackAsItWasWritten) {
  const Json written = sampleRun().toJson();
  EXPECT_EQ(RunRecord::fromJson(written).toJson(), written);
}

TEST(RunRecords, TheRunsKeysAreThoseOfTheResultsFormatInItsOrder) {
  const Json run = sampleRun().toJson();
  std::vector<std::string> keys;
  for (const auto& [key, value] : run.items()) keys.push_back(key);
  const std::vector<std::string> documented = {
      "format",       "version",       "lightcts_revision", "started_utc",    "duration_s",     "command",
      "machine",      "scenes_dir",    "scenes_digest",     "selection",      "baseline_files", "mutants_run",
      "mutant_check", "mutants_not_checked", "evidence_limit", "evidence_url", "jobs",          "shard",
      "reference_cache", "timeout_s",  "flake_retries",     "flakes_fail",    "backends",       "tests",
      "mutants",      "admissible",    "budgets",       "slowest"};
  EXPECT_EQ(keys, documented);
}

TEST(RunRecords, OnlyAMergedRunNamesWhatItWasMergedFrom) {
  RunRecord run = sampleRun();
  EXPECT_FALSE(run.toJson().contains("merged_from"));
  run.mergedFrom = Json::array({{{"dir", "shard-1"}}});
  const Json merged = run.toJson();
  ASSERT_TRUE(merged.contains("merged_from"));
  // Beside the shard it replaces, before the reference cache.
  std::vector<std::string> keys;
  for (const auto& [key, value] : merged.items()) keys.push_back(key);
  const auto at = std::find(keys.begin(), keys.end(), "merged_from");
  EXPECT_EQ(*(at - 1), "shard");
  EXPECT_EQ(*(at + 1), "reference_cache");
}

TEST(RunRecords, ABackendWritesZeroCountsOnlyWhereTheyAreListedWhenZero) {
  BackendRecord b;
  b.counts = {{Verdict::Pass, 3}};
  const Json counts = b.toJson()["counts"];
  EXPECT_EQ(counts["Pass"], 3);
  EXPECT_EQ(counts["Fail"], 0);
  EXPECT_FALSE(counts.contains("Flake"));  // a Flake count is written only when there is one
  EXPECT_EQ(b.toJson()["task_ms"], Json({{"tasks", 0}, {"reference", 0.0}, {"total", 0.0}}));
}

TEST(RunRecords, AWorkerResultWithoutAKnownVerdictIsACrash) {
  EXPECT_EQ(TaskResult::fromJson({{"test", "g.s.vulkan"}}).rawVerdict, Verdict::Crash);
  EXPECT_EQ(TaskResult::fromJson({{"test", "g.s.vulkan"}, {"raw_verdict", "Passed"}}).rawVerdict, Verdict::Crash);
  EXPECT_EQ(TaskResult::fromJson({{"raw_verdict", "QualityWarning"}}).rawVerdict, Verdict::QualityWarning);
}

TEST(RunRecords, ATestThatWasNotRetriedHasNoAttempts) {
  TestRecord t;
  EXPECT_FALSE(t.toJson().contains("attempts"));
}

TEST(RunRecords, SlowestAreTheTenLongestTestsLongestFirst) {
  std::vector<TestRecord> tests(12);
  for (int i = 0; i < 12; ++i) {
    tests[std::size_t(i)].name = "t" + std::to_string(i);
    tests[std::size_t(i)].timingsMs = StageTimes{0, 0, 0, 0, 0, double(i)};
  }
  const std::vector<SlowTest> slowest = slowestTests(tests);
  ASSERT_EQ(slowest.size(), 10u);
  EXPECT_EQ(slowest[0].name, "t11");
  EXPECT_EQ(slowest[9].name, "t2");
}

TEST(RunRecords, AFileThatIsNotResultsIsRefused) {
  EXPECT_THROW(RunRecord::fromJson(Json::array()), std::invalid_argument);
  EXPECT_THROW(RunRecord::fromJson({{"format", "lightcts-bench"}}), std::invalid_argument);
  EXPECT_THROW(RunRecord::fromJson({{"format", "lightcts-results"}, {"tests", {1}}}), std::invalid_argument);
}

}  // namespace
}  // namespace results
