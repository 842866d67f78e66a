#include "runner/expected_failures.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace runner {
namespace {

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
  EXPECT_EQ(fail->status, "Fail");
  EXPECT_EQ(fail->reason, "rounds the range term");
  EXPECT_EQ(fail->source, "drv.txt:3");
  ASSERT_NE(failures.find("stability.range-1e4.gl-egl"), nullptr);
  EXPECT_EQ(failures.find("stability.range-1e4.gl-egl")->reason, "slow");
  EXPECT_EQ(failures.find("limits.popping-64.gl-egl"), nullptr);
}

TEST(ExpectedFailures, EveryLineNeedsAReasonAKnownStatusAndAComma) {
  EXPECT_NE(parseError("a.b.vulkan,Fail\n").find("drv.txt:1: 'a.b.vulkan' has no reason"), std::string::npos);
  EXPECT_NE(parseError("\na.b.vulkan,Pass # no\n").find("drv.txt:2: unknown status 'Pass'"), std::string::npos);
  EXPECT_NE(parseError("a.b.vulkan Fail # x\n").find("expected 'test,Status"), std::string::npos);
  EXPECT_NE(parseError("a.b.vulkan,Fail # x\na.b.vulkan,Crash # y\n").find("listed twice (first at drv.txt:1)"),
            std::string::npos);
}

TEST(ExpectedFailures, BaselineTurnsVerdicts) {
  const ExpectedFailure fail{"Fail", "why", "f:1"};
  EXPECT_EQ(applyExpectation("Fail", &fail), "ExpectedFail");
  EXPECT_EQ(applyExpectation("Pass", &fail), "UnexpectedPass");
  EXPECT_EQ(applyExpectation("Crash", &fail), "Crash");  // a different failure is not the known one
  EXPECT_EQ(applyExpectation("NotSupported", &fail), "NotSupported");
  EXPECT_EQ(applyExpectation("Fail", nullptr), "Fail");
  EXPECT_EQ(applyExpectation("Pass", nullptr), "Pass");
}

}  // namespace
}  // namespace runner
