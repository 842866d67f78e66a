// compareBench on plain Google Benchmark files and bench.json.
#include "reports/bench_compare.h"
#include "reports/tests/bench_sample.h"

#include <gtest/gtest.h>

#include <sstream>

namespace reports {
namespace {

nlohmann::json plain(const std::vector<std::pair<std::string, std::vector<double>>>& runs) {
  return nlohmann::json::parse(testing::plainBenchmarkFile(runs).dump());
}

std::string lineOf(const std::string& text, const std::string& start) {
  const std::size_t at = text.find("\n" + start);
  if (at == std::string::npos) return "";
  return text.substr(at + 1, text.find('\n', at + 1) - at - 1);
}

TEST(BenchCompare, FlagsSignificantRegressions) {
  const auto before = plain({{"same", {10, 10.2, 9.9, 10.1, 10.05}},
                             {"slower", {10, 10.2, 9.9, 10.1, 10.05}},
                             {"faster", {10, 10.2, 9.9, 10.1, 10.05}},
                             {"noisy", {10, 12, 9, 11, 10.5}},
                             {"gone", {1, 1, 1}}});
  const auto after = plain({{"same", {10.05, 10.1, 9.95, 10.0, 10.2}},
                            {"slower", {11, 11.2, 10.9, 11.1, 11.05}},   // +10 %, every time above
                            {"faster", {8, 8.1, 7.9, 8.2, 8.05}},
                            {"noisy", {11, 12.5, 9.5, 11.5, 10}},        // +5 % median, overlapping
                            {"new", {1, 1, 1}}});
  std::ostringstream out;
  EXPECT_EQ(compareBench(before, after, out), 1);
  const std::string text = out.str();
  const std::string slower = lineOf(text, "slower");
  EXPECT_NE(slower.find("+10.0%"), std::string::npos) << slower;
  EXPECT_NE(slower.find("0.0079"), std::string::npos) << slower;
  EXPECT_NE(slower.find("SLOWER"), std::string::npos) << slower;
  EXPECT_NE(lineOf(text, "faster").find("faster (significant)"), std::string::npos) << text;
  EXPECT_EQ(lineOf(text, "same").find("significant"), std::string::npos) << text;
  EXPECT_EQ(lineOf(text, "noisy").find("significant"), std::string::npos) << text;
  EXPECT_NE(text.find("4 benchmarks compared: 2 significant"), std::string::npos) << text;
  EXPECT_NE(text.find("1 only before, 1 only after"), std::string::npos) << text;
}

TEST(BenchCompare, SignificantButSmallIsNoRegression) {
  const auto before = plain({{"a", {10, 10.01, 10.02, 10.03, 10.04}}});
  const auto after = plain({{"a", {10.2, 10.21, 10.22, 10.23, 10.24}}});  // +2 %, significant
  std::ostringstream out;
  EXPECT_EQ(compareBench(before, after, out), 0);
  EXPECT_NE(out.str().find("significant"), std::string::npos);
  EXPECT_EQ(out.str().find("SLOWER"), std::string::npos);
  std::ostringstream strict;
  EXPECT_EQ(compareBench(before, after, strict, CompareOptions{0.05, 1.0}), 1);
}

TEST(BenchCompare, BenchJsonAgainstPlainFile) {
  const nlohmann::json bench = nlohmann::json::parse(testing::sampleBench().dump());
  // The same benchmark as Google Benchmark writes it alone, 30 % slower.
  const auto after = plain({{"frame/vulkan/lights64-1280x720/all-lights/manual_time", {13.2, 12.8, 13, 13.6, 12.9}}});
  std::ostringstream out;
  EXPECT_EQ(compareBench(bench, after, out), 1);
  EXPECT_NE(lineOf(out.str(), "frame/vulkan/lights64-1280x720/all-lights").find("+30.0%"), std::string::npos)
      << out.str();
  std::ostringstream same;
  EXPECT_EQ(compareBench(bench, bench, same), 0);
  EXPECT_EQ(same.str().find("SLOWER"), std::string::npos);
}

}  // namespace
}  // namespace reports
