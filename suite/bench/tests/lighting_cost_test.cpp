// The two halves of the physical limit (docs/performance.md).
#include "suite/bench/lighting_cost.h"
#include "suite/bench/peak_rate.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

namespace {

std::string readDoc(const std::string& relative) {
  std::ifstream in(std::string(LIGHTCTS_SOURCE_DIR) + "/" + relative);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(LightingCost, FlopsPerPixelLightIsTheDocumentedCount) {
  EXPECT_EQ(bench::flopsPerPixelLight(), 45.0);
  // The table of docs/performance.md ends in this row; the code's table
  // (lighting_cost.cpp) is pinned to the same sum by a static_assert.
  const std::string doc = readDoc("docs/performance.md");
  ASSERT_FALSE(doc.empty()) << "docs/performance.md not found";
  EXPECT_NE(doc.find("| **total** | **45** |"), std::string::npos);
}

TEST(PeakRate, KernelResultIsFiniteAndPositive) {
  const bench::PeakRate rate = bench::measurePeakRate(3, 0.02);
  EXPECT_TRUE(std::isfinite(rate.gflops));
  EXPECT_GT(rate.gflops, 0.0);
  EXPECT_TRUE(std::isfinite(rate.checksum));
  EXPECT_GT(rate.checksum, 0.0);
  EXPECT_GE(rate.threads, 1);
  EXPECT_EQ(rate.repetitions, 3);
  EXPECT_FALSE(rate.kernel.empty());
}

TEST(PeakRate, MeasurePeakGflopsIsPositive) {
  const double gflops = bench::measurePeakGflops(1);
  EXPECT_TRUE(std::isfinite(gflops));
  EXPECT_GT(gflops, 0.0);
}

}  // namespace
