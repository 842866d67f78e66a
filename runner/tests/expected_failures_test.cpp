#include "runner/expected_failures.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace runner {
namespace {

using comparison::Verdict;

std::string parseError(const std::string& text) {
  ExpectedFailures failures;
  try {
    failures.parse(text, "drv.txt");
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST(ExpectedFailures, ReadsTestStatusAndReasonSkippingComments) {
  ExpectedFailures failures;
  failures.parse("# lavapipe\n\n  limits.popping-64.vulkan , Fail  # rounds the range term\n"
                 "stability.range-1e4.gl-egl,Timeout#slow\n",
                 "drv.txt");
  const ExpectedFailure* fail = failures.find("limits.popping-64.vulkan");
  ASSERT_NE(fail, nullptr);
  EXPECT_EQ(fail->status, Verdict::Fail);
  EXPECT_EQ(fail->reason, "rounds the range term");
  EXPECT_EQ(fail->source, "drv.txt:3");
  ASSERT_NE(failures.find("stability.range-1e4.gl-egl"), nullptr);
  EXPECT_EQ(failures.find("stability.range-1e4.gl-egl")->reason, "slow");
  EXPECT_EQ(failures.find("stability.range-1e4.gl-egl")->status, Verdict::Timeout);
  EXPECT_EQ(failures.find("limits.popping-64.gl-egl"), nullptr);
}

TEST(ExpectedFailures, EveryLineNeedsAReasonAKnownStatusAndAComma) {
  EXPECT_NE(parseError("a.b.vulkan,Fail\n").find("drv.txt:1: 'a.b.vulkan' has no reason"), std::string::npos);
  EXPECT_NE(parseError("\na.b.vulkan,Pass # no\n").find("drv.txt:2: unknown status 'Pass'"), std::string::npos);
  EXPECT_NE(parseError("a.b.vulkan Fail # x\n").find("expected 'test,Status"), std::string::npos);
  EXPECT_NE(parseError("a.b.vulkan,Fail # x\na.b.vulkan,Crash # y\n").find("listed twice (first at drv.txt:1)"),
            std::string::npos);
}

// The statuses a line may name: the failing verdicts of SPEC 7, spelt exactly.
TEST(ExpectedFailures, OnlyFailingVerdictsMayBeExpected) {
  for (const char* status : {"Fail", "Crash", "Timeout", "QualityWarning"})
    EXPECT_EQ(parseError(std::string("a.b.vulkan,") + status + " # x\n"), "") << status;
  for (const char* status : {"Pass", "NotSupported", "ExpectedFail", "UnexpectedPass", "Flake", "fail", "CRASH"})
    EXPECT_NE(parseError(std::string("a.b.vulkan,") + status + " # x\n").find(std::string("unknown status '") +
                                                                             status + "'"),
              std::string::npos)
        << status;
  EXPECT_NE(parseError("a.b.vulkan,Pass # x\n").find("expected Fail, QualityWarning, Crash or Timeout"),
            std::string::npos);
}

TEST(ExpectedFailures, BaselineTurnsVerdicts) {
  const ExpectedFailure fail{Verdict::Fail, "why", "f:1"};
  EXPECT_EQ(applyExpectation(Verdict::Fail, &fail), Verdict::ExpectedFail);
  EXPECT_EQ(applyExpectation(Verdict::Pass, &fail), Verdict::UnexpectedPass);
  EXPECT_EQ(applyExpectation(Verdict::Crash, &fail), Verdict::Crash);  // a different failure is not the known one
  EXPECT_EQ(applyExpectation(Verdict::NotSupported, &fail), Verdict::NotSupported);
  EXPECT_EQ(applyExpectation(Verdict::Fail, nullptr), Verdict::Fail);
  EXPECT_EQ(applyExpectation(Verdict::Pass, nullptr), Verdict::Pass);
  const ExpectedFailure timeout{Verdict::Timeout, "slow", "f:2"};
  EXPECT_EQ(applyExpectation(Verdict::Timeout, &timeout), Verdict::ExpectedFail);
  EXPECT_EQ(applyExpectation(Verdict::Fail, &timeout), Verdict::Fail);
}

// A driver's deviation stays under a legal implementation: a scene's line
// covers its admissible variants' tests, where a pass is a pass (the variant
// may step around the fault); a line of the variant's own test is exact.
TEST(ExpectedFailures, AScenesLineCoversItsAdmissibleVariantsTests) {
  ExpectedFailures failures;
  failures.parse("a.b.vulkan,Fail # the driver's fault\na.c@quotient-up.vulkan,Fail # this variant's\n", "drv.txt");
  const ExpectedFailure* inherited = failures.find("a.b@snap-up.vulkan");
  ASSERT_NE(inherited, nullptr);
  EXPECT_TRUE(inherited->inherited);
  EXPECT_EQ(applyExpectation(Verdict::Fail, inherited), Verdict::ExpectedFail);
  EXPECT_EQ(applyExpectation(Verdict::Pass, inherited), Verdict::Pass);
  EXPECT_NE(inherited->reason.find("listed for a.b.vulkan"), std::string::npos);
  EXPECT_EQ(failures.find("a.b@snap-up.gl-egl"), nullptr);  // another combination's test
  const ExpectedFailure* own = failures.find("a.c@quotient-up.vulkan");
  ASSERT_NE(own, nullptr);
  EXPECT_FALSE(own->inherited);
  EXPECT_EQ(applyExpectation(Verdict::Pass, own), Verdict::UnexpectedPass);
  EXPECT_EQ(failures.find("a.c@quotient-down.vulkan"), nullptr);  // no line for a.c's model test
}

}  // namespace
}  // namespace runner
