// The rules of a result, against cases worked out by hand from
// docs/results-format.md.
#include "results/result_rules.h"

#include <gtest/gtest.h>

namespace results {
namespace {

using comparison::BackendStatus;
using comparison::MutantStatus;
using comparison::Verdict;

TEST(ResultRules, ABackendRanWhenEveryPartRan) {
  const auto s = combinedBackendStatus({{BackendStatus::Ran, ""}, {BackendStatus::Ran, ""}}, "gone: ");
  EXPECT_EQ(s.status, BackendStatus::Ran);
  EXPECT_EQ(s.message, "");
}

TEST(ResultRules, APartInErrorPutsTheBackendInErrorWithItsMessage) {
  const auto s = combinedBackendStatus(
      {{BackendStatus::Ran, ""}, {BackendStatus::Error, "first"}, {BackendStatus::Error, "second"}}, "gone: ");
  EXPECT_EQ(s.status, BackendStatus::Error);
  EXPECT_EQ(s.message, "first");
}

TEST(ResultRules, ABackendAbsentEverywhereIsNotSupported) {
  const auto s = combinedBackendStatus({{BackendStatus::NotSupported, "no ICD"}, {BackendStatus::NotSupported, "x"}}, "gone: ");
  EXPECT_EQ(s.status, BackendStatus::NotSupported);
  EXPECT_EQ(s.message, "no ICD");
}

TEST(ResultRules, ABackendAbsentInSomePartsIsAnError) {
  const auto s = combinedBackendStatus({{BackendStatus::Ran, ""}, {BackendStatus::NotSupported, "no ICD"}}, "gone: ");
  EXPECT_EQ(s.status, BackendStatus::Error);
  EXPECT_EQ(s.message, "gone: no ICD");
}

TEST(ResultRules, AKillOutranksEveryOtherObservation) {
  EXPECT_EQ(mutantStatus({true, true, true, true, true}), MutantStatus::Killed);
  EXPECT_EQ(mutantStatus({false, true, true, true, true}), MutantStatus::NotSupported);
  EXPECT_EQ(mutantStatus({false, false, true, true, true}), MutantStatus::Crash);
  EXPECT_EQ(mutantStatus({false, false, false, true, true}), MutantStatus::Timeout);
  EXPECT_EQ(mutantStatus({false, false, false, false, true}), MutantStatus::NotRun);
  EXPECT_EQ(mutantStatus({}), MutantStatus::Survived);
}

TEST(ResultRules, ShardsJoinAMutantKilledInAnyAndAbsentOnlyWhereAbsentInAll) {
  const auto killedHere = observationsOf(MutantStatus::Killed);
  const auto absentThere = observationsOf(MutantStatus::NotSupported);
  const auto survivedThere = observationsOf(MutantStatus::Survived);
  EXPECT_EQ(mutantStatus(joined(survivedThere, killedHere)), MutantStatus::Killed);
  EXPECT_EQ(mutantStatus(joined(absentThere, survivedThere)), MutantStatus::Survived);
  EXPECT_EQ(mutantStatus(joined(absentThere, absentThere)), MutantStatus::NotSupported);
  for (const MutantStatus s : {MutantStatus::Killed, MutantStatus::Survived, MutantStatus::NotSupported,
                               MutantStatus::Crash, MutantStatus::Timeout, MutantStatus::NotRun})
    EXPECT_EQ(mutantStatus(observationsOf(s)), s);
}

TestRecord test(Verdict verdict, const std::string& backend = "vulkan") {
  TestRecord t;
  t.backend = backend;
  t.verdict = verdict;
  return t;
}

MutantRecord mutant(MutantStatus status, const std::string& backend = "vulkan") {
  MutantRecord m;
  m.backend = backend;
  m.status = status;
  return m;
}

BackendRecord backend(BackendStatus status) {
  BackendRecord b;
  b.status = status;
  return b;
}

TEST(ResultRules, CountsAreOfOneBackend) {
  const std::vector<TestRecord> tests = {test(Verdict::Pass), test(Verdict::Fail), test(Verdict::Pass, "gl-egl")};
  EXPECT_EQ(countVerdicts(tests, "vulkan"), (std::map<Verdict, int>{{Verdict::Pass, 1}, {Verdict::Fail, 1}}));
  const std::vector<MutantRecord> mutants = {mutant(MutantStatus::Killed), mutant(MutantStatus::Crash),
                                             mutant(MutantStatus::NotSupported),
                                             mutant(MutantStatus::Survived, "gl-egl")};
  EXPECT_EQ(countMutants(mutants, "vulkan"), (MutantCounts{1, 0, 2}));
  EXPECT_EQ(countMutants(mutants, "gl-egl"), (MutantCounts{0, 1, 0}));
}

TestRecord variantTest(const std::string& variant, Verdict verdict, const std::string& backendName = "vulkan") {
  TestRecord t = test(verdict, backendName);
  t.admissible = variant;
  t.name = "g.s@" + variant + "." + backendName;
  return t;
}

// A variant's tests count apart from the model's; its status over them:
// a Fail (or an UnexpectedPass) is unsound, a crash leaves it incomplete,
// every test NotSupported is NotSupported, and expected failures are sound.
TEST(ResultRules, AnAdmissibleVariantIsSoundUnlessOneOfItsTestsFails) {
  const std::vector<TestRecord> tests = {
      test(Verdict::Pass),
      variantTest("snap-up", Verdict::Pass),
      variantTest("snap-up", Verdict::ExpectedFail),
      variantTest("quotient-up", Verdict::Pass),
      variantTest("quotient-up", Verdict::Fail),
      variantTest("quotient-up", Verdict::Crash),
      variantTest("snap-down", Verdict::Crash),
      variantTest("snap-down", Verdict::Pass),
      variantTest("snap-up", Verdict::NotSupported, "gl-egl")};
  EXPECT_EQ(countVerdicts(tests, "vulkan"), (std::map<Verdict, int>{{Verdict::Pass, 1}}));
  EXPECT_EQ(countAdmissibleVerdicts(tests, "vulkan"),
            (std::map<Verdict, int>{{Verdict::Pass, 3}, {Verdict::ExpectedFail, 1}, {Verdict::Fail, 1},
                                    {Verdict::Crash, 2}}));
  const std::vector<AdmissibleRecord> records = admissibleRecords(tests);
  ASSERT_EQ(records.size(), 4u);
  EXPECT_EQ(records[0].variant, "snap-up");
  EXPECT_EQ(records[0].status, comparison::AdmissibleStatus::Sound);
  EXPECT_EQ(records[0].tests, 2);
  EXPECT_EQ(records[0].expected, (std::vector<std::string>{"g.s@snap-up.vulkan"}));
  EXPECT_EQ(records[1].status, comparison::AdmissibleStatus::Unsound);
  EXPECT_EQ(records[1].failed.size(), 2u);  // the Fail and the Crash
  EXPECT_EQ(records[2].status, comparison::AdmissibleStatus::Incomplete);
  EXPECT_EQ(records[3].backend, "gl-egl");
  EXPECT_EQ(records[3].status, comparison::AdmissibleStatus::NotSupported);
}

RunRecord passingRun() {
  RunRecord run;
  run.tests = {test(Verdict::Pass), test(Verdict::ExpectedFail), test(Verdict::Flake)};
  run.backends = {backend(BackendStatus::Ran), backend(BackendStatus::NotSupported)};
  run.mutants = {mutant(MutantStatus::Killed), mutant(MutantStatus::NotSupported)};
  return run;
}

TEST(ResultRules, ARunPassesWithPassesExpectedFailuresFlakesAndSkips) { EXPECT_TRUE(runPasses(passingRun())); }

TEST(ResultRules, ARunFailsOnAFailureAnErrorOrAMutantThatFailedItsCheck) {
  for (const Verdict v : {Verdict::Fail, Verdict::Crash, Verdict::Timeout, Verdict::UnexpectedPass}) {
    RunRecord run = passingRun();
    run.tests.push_back(test(v));
    EXPECT_FALSE(runPasses(run)) << comparison::verdictName(v);
  }
  RunRecord error = passingRun();
  error.backends.push_back(backend(BackendStatus::Error));
  EXPECT_FALSE(runPasses(error));
  for (const MutantStatus s : {MutantStatus::Survived, MutantStatus::Crash, MutantStatus::Timeout}) {
    RunRecord run = passingRun();
    run.mutants.push_back(mutant(s));
    EXPECT_FALSE(runPasses(run)) << comparison::mutantStatusName(s);
  }
}

TEST(ResultRules, FlakesFailARunOnlyWhenFlakesFailIsSet) {
  RunRecord run = passingRun();
  run.flakesFail = true;
  EXPECT_FALSE(runPasses(run));
}

TEST(ResultRules, AShardPassesWithASurvivorThatAnotherShardMayKill) {
  RunRecord shard = passingRun();
  shard.shard = ShardRecord{};
  shard.shard->index = 1;
  shard.shard->total = 2;
  shard.mutants.push_back(mutant(MutantStatus::Survived));
  EXPECT_TRUE(runPasses(shard));
  shard.mutants.push_back(mutant(MutantStatus::Crash));
  EXPECT_FALSE(runPasses(shard));
}

}  // namespace
}  // namespace results
