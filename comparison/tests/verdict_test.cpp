// The verdicts' names and meanings. The expected values are written out here
// from SPEC 7 and docs/results-format.md, not computed from verdict.cpp.
#include "comparison/verdict.h"

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

namespace comparison {
namespace {

TEST(Verdict, NamesAreTheWordsOfResultsJsonInReportOrder) {
  std::vector<std::string> names;
  for (const Verdict verdict : kAllVerdicts) names.emplace_back(verdictName(verdict));
  const std::vector<std::string> expected = {"Pass",    "Fail",         "QualityWarning", "NotSupported", "Crash",
                                             "Timeout", "ExpectedFail", "UnexpectedPass", "Flake",
                                             "NotRun"};
  EXPECT_EQ(names, expected);
}

TEST(Verdict, EveryVerdictRoundTripsThroughNameAndParse) {
  for (const Verdict verdict : kAllVerdicts) {
    const std::optional<Verdict> parsed = parseVerdict(verdictName(verdict));
    ASSERT_TRUE(parsed.has_value()) << verdictName(verdict);
    EXPECT_EQ(*parsed, verdict);
  }
}

TEST(Verdict, ParseRejectsUnknownAndWronglyCasedNames) {
  for (const char* name : {"", "Maybe", "pass", "PASS", "fail", "notsupported", "Not Supported", "Expected Fail",
                           "flake", " Pass", "Pass ", "killed", "ran", "error"})
    EXPECT_FALSE(parseVerdict(name).has_value()) << "'" << name << "'";
}

TEST(Verdict, PrintsItsName) {
  std::ostringstream out;
  out << Verdict::UnexpectedPass << ' ' << Verdict::Flake;
  EXPECT_EQ(out.str(), "UnexpectedPass Flake");
}

// `lightcts run` exits 1 on these (SPEC 8, docs/results-format.md).
TEST(Verdict, RunFailures) {
  EXPECT_FALSE(isRunFailure(Verdict::Pass));
  EXPECT_TRUE(isRunFailure(Verdict::Fail));
  EXPECT_FALSE(isRunFailure(Verdict::QualityWarning));
  EXPECT_FALSE(isRunFailure(Verdict::NotSupported));  // a skip, never a pass, but not a failure either
  EXPECT_TRUE(isRunFailure(Verdict::Crash));
  EXPECT_TRUE(isRunFailure(Verdict::Timeout));
  EXPECT_FALSE(isRunFailure(Verdict::ExpectedFail));
  EXPECT_TRUE(isRunFailure(Verdict::UnexpectedPass));  // a fixed bug: the baseline line must go
  EXPECT_FALSE(isRunFailure(Verdict::Flake));          // it passed on a retry
  EXPECT_TRUE(isRunFailure(Verdict::NotRun));          // an interrupted run proves nothing
}

TEST(Verdict, CiOutcomes) {
  EXPECT_EQ(ciOutcome(Verdict::Pass), CiOutcome::Pass);
  EXPECT_EQ(ciOutcome(Verdict::Fail), CiOutcome::Failure);
  EXPECT_EQ(ciOutcome(Verdict::QualityWarning), CiOutcome::Skipped);  // checked nothing: no pass
  EXPECT_EQ(ciOutcome(Verdict::NotSupported), CiOutcome::Skipped);
  EXPECT_EQ(ciOutcome(Verdict::Crash), CiOutcome::Error);
  EXPECT_EQ(ciOutcome(Verdict::Timeout), CiOutcome::Error);
  EXPECT_EQ(ciOutcome(Verdict::ExpectedFail), CiOutcome::Skipped);
  EXPECT_EQ(ciOutcome(Verdict::UnexpectedPass), CiOutcome::Failure);
  EXPECT_EQ(ciOutcome(Verdict::Flake), CiOutcome::Pass);
  EXPECT_EQ(ciOutcome(Verdict::NotRun), CiOutcome::Error);  // it did not run to its end
}

TEST(Verdict, RunFailuresAreExactlyTheCiFailuresAndErrors) {
  for (const Verdict verdict : kAllVerdicts) {
    const CiOutcome outcome = ciOutcome(verdict);
    EXPECT_EQ(isRunFailure(verdict), outcome == CiOutcome::Failure || outcome == CiOutcome::Error) << verdict;
  }
}

TEST(Verdict, NeedsAttention) {
  EXPECT_FALSE(needsAttention(Verdict::Pass));
  EXPECT_TRUE(needsAttention(Verdict::Fail));
  EXPECT_TRUE(needsAttention(Verdict::QualityWarning));
  EXPECT_FALSE(needsAttention(Verdict::NotSupported));
  EXPECT_TRUE(needsAttention(Verdict::Crash));
  EXPECT_TRUE(needsAttention(Verdict::Timeout));
  EXPECT_FALSE(needsAttention(Verdict::ExpectedFail));
  EXPECT_TRUE(needsAttention(Verdict::UnexpectedPass));
  EXPECT_TRUE(needsAttention(Verdict::Flake));
  EXPECT_FALSE(needsAttention(Verdict::NotRun));  // no evidence to look at
}

TEST(Verdict, ExpectableAreTheFailingVerdictsOfSpec7) {
  std::vector<Verdict> expectable;
  for (const Verdict verdict : kAllVerdicts)
    if (isExpectable(verdict)) expectable.push_back(verdict);
  EXPECT_EQ(expectable,
            (std::vector<Verdict>{Verdict::Fail, Verdict::QualityWarning, Verdict::Crash, Verdict::Timeout}));
}

TEST(Verdict, CountTablesListFlakeAndNotRunOnlyWhenOneOccurred) {
  for (const Verdict verdict : kAllVerdicts)
    EXPECT_EQ(listedWhenZero(verdict), verdict != Verdict::Flake && verdict != Verdict::NotRun) << verdict;
}

}  // namespace
}  // namespace comparison
