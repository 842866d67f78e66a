#include "runner/run_plan.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace runner {
namespace {

// The m-th mutant of the table (any will do: the plan only groups by mutant).
shaders::Mutant mutantNumber(int m) { return shaders::Mutant(m + 1); }

RunUnit unit(std::size_t combination, const std::string& test, int mutants, bool model = true) {
  RunUnit u{combination, test, {}};
  if (model) u.tasks.push_back({test, test + ".json", shaders::Mutant::None});
  for (int m = 0; m < mutants; ++m) u.tasks.push_back({test, test + ".json", mutantNumber(m)});
  return u;
}

TEST(RunPlan, ShardIsOneBasedIOfN) {
  EXPECT_EQ(parseShard("2/3").index, 2);
  EXPECT_EQ(parseShard("2/3").total, 3);
  EXPECT_EQ(parseShard("1/1").total, 1);
  for (const char* bad : {"0/3", "4/3", "3", "a/b", "1/0", "1/3x", "/3", "-1/3", ""})
    EXPECT_THROW(parseShard(bad), std::invalid_argument) << bad;
}

// Longest first onto the least loaded shard, by hand: costs 5 4 3 3 2 1 on
// two shards go 5->A, 4->B, 3->B (4 < 5), 3->A (5 < 7), 2->B (7 < 8),
// 1->A (8 < 9): loads 9 and 9.
TEST(RunPlan, GreedyLongestFirstOntoTheLeastLoaded) {
  EXPECT_EQ(assignShards({5, 4, 3, 3, 2, 1}, 2), (std::vector<int>{0, 1, 1, 0, 1, 0}));
  // Equal costs (balance by count): round robin in unit order.
  EXPECT_EQ(assignShards({1, 1, 1, 1, 1, 1, 1}, 3), (std::vector<int>{0, 1, 2, 0, 1, 2, 0}));
}

TEST(RunPlan, EveryUnitInExactlyOneShard) {
  std::vector<double> costs;
  for (int i = 0; i < 101; ++i) costs.push_back(double((i * 37) % 11) + 0.5);
  for (int total : {1, 2, 3, 7}) {
    const std::vector<int> shardOf = assignShards(costs, total);
    ASSERT_EQ(shardOf.size(), costs.size());
    std::vector<int> perShard(std::size_t(total), 0);
    for (int s : shardOf) {
      ASSERT_GE(s, 0);
      ASSERT_LT(s, total);
      ++perShard[std::size_t(s)];
    }
    for (int n : perShard) EXPECT_GT(n, 0) << "a shard of " << total << " is empty";
  }
}

TEST(RunPlan, CostsByCountOrByTimings) {
  const std::vector<RunUnit> units = {unit(0, "a.x.vulkan", 2), unit(0, "a.y.vulkan", 2)};
  EXPECT_EQ(unitCosts(units, std::nullopt), (std::vector<double>{3, 3}));
  // a.x: the model test 10 ms, of which the reference 6: each mutant task
  // costs 10 - 6 = 4, so 10 + 2 * 4 = 18. a.y is unknown: the known mean per
  // task (18 / 3 = 6) times its 3 tasks.
  const Timings timings = {{"a.x.vulkan", {10, 6}}};
  EXPECT_EQ(unitCosts(units, timings), (std::vector<double>{18, 18}));
}

TEST(RunPlan, TimingsComeFromAResultsFile) {
  const auto file = std::filesystem::temp_directory_path() / "lightcts-run-plan-timings.json";
  std::ofstream(file) << R"({"format": "lightcts-results", "backends": [], "tests": [)"
                         R"({"name": "a.x.vulkan", "backend": "vulkan", "verdict": "Pass",)"
                         R"( "timings_ms": {"total": 12.5, "reference": 2}},)"
                         R"({"name": "a.y.vulkan", "backend": "vulkan", "verdict": "Crash", "timings_ms": null}]})";
  const Timings timings = loadTimings(file.string());
  ASSERT_EQ(timings.size(), 1u);
  EXPECT_EQ(timings.at("a.x.vulkan").totalMs, 12.5);
  EXPECT_EQ(timings.at("a.x.vulkan").referenceMs, 2);
  std::ofstream(file) << R"({"format": "lightcts-bench"})";
  EXPECT_THROW(loadTimings(file.string()), std::invalid_argument);
  EXPECT_THROW(loadTimings("/nonexistent/results.json"), std::invalid_argument);
  std::filesystem::remove(file);
}

// 30 model tests split 24 + 6; each mutant over 30 scenes (more than a part
// holds) is a part of its own; on the second combination the two mutants of
// one task each share a part.
TEST(RunPlan, PartsSplitTheModelAndKeepEachMutantWhole) {
  std::vector<RunUnit> units;
  for (int s = 0; s < 30; ++s) units.push_back(unit(0, "g.s" + std::to_string(100 + s) + ".vulkan", 2));
  units.push_back(unit(1, "g.s100.gl-egl", 2));
  const std::vector<WorkerPart> parts = workerParts(units, 2);
  ASSERT_EQ(parts.size(), 4u + 2u);
  EXPECT_EQ(parts[0].tasks.size(), kModelTestsPerPart);
  EXPECT_EQ(parts[1].tasks.size(), 30 - kModelTestsPerPart);
  EXPECT_EQ(parts[2].tasks.size(), 30u);
  EXPECT_EQ(parts[2].tasks.front().mutant, mutantNumber(0));
  EXPECT_EQ(parts[3].tasks.back().mutant, mutantNumber(1));
  EXPECT_EQ(parts[3].number, 3);
  EXPECT_EQ(parts[4].combination, 1u);
  EXPECT_EQ(parts[4].number, 0);
  ASSERT_EQ(parts[5].tasks.size(), 2u);
  EXPECT_EQ(parts[5].tasks[0].mutant, mutantNumber(0));
  EXPECT_EQ(parts[5].tasks[1].mutant, mutantNumber(1));
  for (const WorkerTask& t : parts[0].tasks) EXPECT_TRUE(t.isModelTest());
}

TEST(RunPlan, SmallMutantsArePackedWholeIntoParts) {
  // 3 scenes, 20 mutants each with one task per scene (3 tasks): 8 mutants
  // (24 tasks) fill a part, so the parts hold 8, 8 and 4 mutants.
  std::vector<RunUnit> units;
  for (int s = 0; s < 3; ++s) units.push_back(unit(0, "g.s" + std::to_string(s) + ".vulkan", 20));
  const std::vector<WorkerPart> parts = workerParts(units, 1);
  ASSERT_EQ(parts.size(), 1u + 3u);
  EXPECT_EQ(parts[0].tasks.size(), 3u);
  EXPECT_EQ(parts[1].tasks.size(), 24u);
  EXPECT_EQ(parts[2].tasks.size(), 24u);
  EXPECT_EQ(parts[3].tasks.size(), 12u);
  // Each mutant whole in one part, in order: the ninth mutant starts the second part.
  EXPECT_EQ(parts[1].tasks.back().mutant, mutantNumber(7));
  EXPECT_EQ(parts[2].tasks.front().mutant, mutantNumber(8));
  EXPECT_EQ(parts[3].tasks.back().mutant, mutantNumber(19));
}

// An admissible variant's tests go together, after the model's and in
// parts of their own, each whole, as a mutant's do: a backend is built for
// one shader variant.
TEST(RunPlan, AnAdmissibleVariantsTestsKeepTogether) {
  std::vector<RunUnit> units;
  for (int s = 0; s < 3; ++s) {
    const std::string test = "g.s" + std::to_string(s) + ".vulkan";
    RunUnit u{0, test, {{test, "x.json"}}};
    for (const shaders::Admissible variant : {shaders::Admissible::QuotientUp, shaders::Admissible::SnapDown})
      u.tasks.push_back({admissibleTestName("g.s" + std::to_string(s), variant, "vulkan"), "x.json",
                         shaders::Mutant::None, variant});
    units.push_back(u);
  }
  const std::vector<WorkerPart> parts = workerParts(units, 1);
  ASSERT_EQ(parts.size(), 2u);  // the model's 3, then both variants' 6 packed in one part
  EXPECT_EQ(parts[0].tasks.size(), 3u);
  ASSERT_EQ(parts[1].tasks.size(), 6u);
  EXPECT_EQ(parts[1].tasks[0].test, "g.s0@quotient-up.vulkan");
  EXPECT_EQ(parts[1].tasks[2].test, "g.s2@quotient-up.vulkan");
  EXPECT_EQ(parts[1].tasks[3].test, "g.s0@snap-down.vulkan");
  for (const WorkerTask& task : parts[1].tasks) EXPECT_FALSE(task.isModelTest() || task.isMutantTask());
  EXPECT_EQ(caseOfTest("g.s0@snap-down.vulkan"), "g.s0");
  EXPECT_EQ(caseOfTest("g.s0.vulkan"), "g.s0");
}

TEST(RunPlan, PartitionDigestNamesThePartition) {
  const std::vector<RunUnit> units = {unit(0, "a.x.vulkan", 1), unit(0, "a.y.vulkan", 1)};
  const std::string digest = partitionDigest(units, {0, 1}, 2);
  EXPECT_EQ(digest.size(), 64u);
  EXPECT_EQ(digest, partitionDigest(units, {0, 1}, 2));
  EXPECT_NE(digest, partitionDigest(units, {1, 0}, 2));
  EXPECT_NE(digest, partitionDigest(units, {0, 1}, 3));
  EXPECT_NE(digest, partitionDigest({unit(0, "a.x.vulkan", 2), unit(0, "a.y.vulkan", 1)}, {0, 1}, 2));
}

}  // namespace
}  // namespace runner
