// The JSON file reporter of the benchmark programs (suite/bench/bench_reporters.h):
// a non-finite counter is written as null, never as 0 and never as Google
// Benchmark's NaN / Infinity (not JSON); only the cv of a counter whose mean
// is 0 (0/0: nothing varied) is written as 0.
#include "suite/bench/bench_reporters.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace {

using Run = benchmark::BenchmarkReporter::Run;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

Run run(const std::string& aggregate, const benchmark::UserCounters& counters) {
  Run r;
  r.run_name.function_name = "frame/vulkan/lights64-1280x720/deferred-ldr8";
  r.run_name.repetitions = "repeats:2";
  r.family_index = 0;
  r.per_family_instance_index = 0;
  r.repetitions = 2;
  r.repetition_index = aggregate.empty() ? 0 : Run::no_repetition_index;
  r.run_type = aggregate.empty() ? Run::RT_Iteration : Run::RT_Aggregate;
  r.aggregate_name = aggregate;
  r.iterations = 4;
  r.real_accumulated_time = r.cpu_accumulated_time = 0.04;
  r.time_unit = benchmark::kMillisecond;
  r.counters = counters;
  return r;
}

// What the file reporter writes for one repetition and the mean and cv aggregates.
nlohmann::json reported(const benchmark::UserCounters& repetition, const benchmark::UserCounters& mean,
                        const benchmark::UserCounters& cv) {
  const bench::Reporters reporters = bench::plainNameReporters({"--benchmark_out=bench.json"});
  EXPECT_TRUE(reporters.file);
  benchmark::BenchmarkReporter::Context::executable_name = "bench_reporters_tests";  // Initialize's job
  std::ostringstream out;
  reporters.file->SetOutputStream(&out);
  reporters.file->SetErrorStream(&out);
  reporters.file->ReportContext(benchmark::BenchmarkReporter::Context());
  reporters.file->ReportRuns({run("", repetition)});
  reporters.file->ReportRuns({run("mean", mean), run("cv", cv)});
  reporters.file->Finalize();
  return nlohmann::json::parse(out.str());  // throws on NaN or Infinity
}

TEST(BenchReporters, NonFiniteCountersAreNullNotZero) {
  const nlohmann::json j = reported({{"err_rmse", kNaN}, {"err_max_abs", kInf}, {"err_psnr_db", -kInf},
                                     {"err_nonfinite_pixels", 12.0}},
                                    {{"err_max_abs", kInf}}, {{"err_max_abs", kNaN}});
  const nlohmann::json& b = j.at("benchmarks");
  ASSERT_EQ(b.size(), 3u);
  EXPECT_EQ(b[0].at("name"), "frame/vulkan/lights64-1280x720/deferred-ldr8");  // plain name
  EXPECT_TRUE(b[0].at("err_rmse").is_null()) << b[0];
  EXPECT_TRUE(b[0].at("err_max_abs").is_null()) << b[0];
  EXPECT_TRUE(b[0].at("err_psnr_db").is_null()) << b[0];
  EXPECT_EQ(b[0].at("err_nonfinite_pixels"), 12.0);
  EXPECT_TRUE(b[1].at("err_max_abs").is_null()) << b[1];  // mean of infinities
  EXPECT_TRUE(b[2].at("err_max_abs").is_null()) << b[2];  // their cv: no 0/0, unknown
}

TEST(BenchReporters, CvOfAnAlwaysZeroCounterIsZero) {
  const nlohmann::json j = reported({{"demoted", 0.0}, {"lights", 64.0}}, {{"demoted", 0.0}, {"lights", 64.0}},
                                    {{"demoted", kNaN}, {"lights", 0.0}});
  const nlohmann::json& cv = j.at("benchmarks").at(2);
  EXPECT_EQ(cv.at("aggregate_name"), "cv");
  EXPECT_EQ(cv.at("demoted"), 0.0);
  EXPECT_EQ(cv.at("lights"), 0.0);
}

TEST(BenchReporters, NullForNonFiniteLeavesStringsAlone) {
  EXPECT_EQ(bench::nullForNonFinite(R"({"a": NaN, "b": -Infinity, "c": inf, "name": "NaN: Infinity", "d": 1})"),
            R"({"a": null, "b": null, "c": null, "name": "NaN: Infinity", "d": 1})");
}

}  // namespace
