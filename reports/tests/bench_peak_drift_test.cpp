// The loaded-machine flag: the peak-rate calibrations before and
// after the timed runs, compared as |after - before| / min(before, after)
// against 0.2. The expected values are worked out by hand in each test.
#include "reports/bench_report.h"
#include "reports/tests/bench_sample.h"

#include <gtest/gtest.h>

namespace reports {
namespace {

using Json = nlohmann::ordered_json;

TEST(BenchPeakDrift, AQuarterMoreIsFlagged) {
  // |125 - 100| / 100 = 0.25 > 0.2.
  const auto drift = peakDrift(100.0, 125.0);
  ASSERT_TRUE(drift.has_value());
  EXPECT_DOUBLE_EQ(drift->difference, 0.25);
  EXPECT_TRUE(drift->flagged);
}

TEST(BenchPeakDrift, FifteenPercentIsNotFlagged) {
  // |115 - 100| / 100 = 0.15 <= 0.2.
  const auto drift = peakDrift(100.0, 115.0);
  ASSERT_TRUE(drift.has_value());
  EXPECT_DOUBLE_EQ(drift->difference, 0.15);
  EXPECT_FALSE(drift->flagged);
}

TEST(BenchPeakDrift, SymmetricInTheTwoCalibrations) {
  // A fall from 125 to 100 is the same 25 / min(125, 100) = 0.25, so a run
  // that got loaded halfway is flagged as one that got quiet.
  const auto drift = peakDrift(125.0, 100.0);
  ASSERT_TRUE(drift.has_value());
  EXPECT_DOUBLE_EQ(drift->difference, 0.25);
  EXPECT_TRUE(drift->flagged);
}

TEST(BenchPeakDrift, TheLimitItselfIsNotFlagged) {
  // 120 against 100: 20 / 100 is exactly 0.2 in real numbers, and IEEE
  // division rounds it to the same double as the literal 0.2; the rule is
  // "more than 20%", so it is not flagged.
  const auto atLimit = peakDrift(100.0, 120.0);
  ASSERT_TRUE(atLimit.has_value());
  EXPECT_DOUBLE_EQ(atLimit->difference, 0.2);
  EXPECT_FALSE(atLimit->flagged);
}

TEST(BenchPeakDrift, TheIssuesLoadedAgainstQuietRatesAreFlagged) {
  // Rates measured on one 2-core machine: 109 GFLOP/s under load against
  // 426 quiet: 317 / 109 = 2.9.
  const auto drift = peakDrift(426.0, 109.0);
  ASSERT_TRUE(drift.has_value());
  EXPECT_NEAR(drift->difference, 317.0 / 109.0, 1e-12);
  EXPECT_TRUE(drift->flagged);
}

TEST(BenchPeakDrift, NoComparisonWithoutBothRates) {
  EXPECT_FALSE(peakDrift(std::nullopt, 100.0).has_value());
  EXPECT_FALSE(peakDrift(100.0, std::nullopt).has_value());
  EXPECT_FALSE(peakDrift(0.0, 100.0).has_value());
  Json bench = {{"format", "lightcts-bench"}, {"peak", {{"gflops", 100.0}}}};
  EXPECT_FALSE(peakDriftOf(bench).has_value());  // an older file: "peak" only
  bench["peak_after"] = nullptr;                 // the second calibration failed
  EXPECT_FALSE(peakDriftOf(bench).has_value());
}

Json withPeaks(double before, double after) {
  Json bench = reports::testing::sampleBench();
  bench["peak"]["gflops"] = before;
  bench["peak_after"] = {{"gflops", after}};
  return bench;
}

TEST(BenchPeakDrift, PagesWarnOfALoadedMachine) {
  const Json loaded = withPeaks(100.0, 125.0);
  const std::string warning = "id=\"peak-drift\"";
  EXPECT_NE(benchOverviewHtml(loaded).find(warning), std::string::npos);
  for (const std::string& backend : benchBackends(loaded))
    EXPECT_NE(benchBackendHtml(loaded, backend).find(warning), std::string::npos) << backend;
  // The difference as a percentage: 25%.
  EXPECT_NE(benchOverviewHtml(loaded).find("differ by 25%"), std::string::npos);
}

TEST(BenchPeakDrift, PagesOfAQuietRunCarryNoWarning) {
  const Json quiet = withPeaks(100.0, 115.0);
  EXPECT_EQ(benchOverviewHtml(quiet).find("id=\"peak-drift\""), std::string::npos);
  for (const std::string& backend : benchBackends(quiet))
    EXPECT_EQ(benchBackendHtml(quiet, backend).find("id=\"peak-drift\""), std::string::npos) << backend;
  EXPECT_NE(benchOverviewHtml(quiet).find("peak rate after"), std::string::npos);
}

}  // namespace
}  // namespace reports
