#include "reports/csv_writer.h"
#include "imaging/tests/scratch_folder_test.h"
#include "reports/tests/sample_results.h"
#include "runner/expected_failures.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace reports {
namespace {

namespace fs = std::filesystem;
using comparison::Verdict;

using imaging::testing::readFile;

TEST(RunCsv, ResultsListEveryTestWithItsVerdictAndSeconds) {
  EXPECT_EQ(resultsCsv(testing::records(testing::sampleResults())),
            "attenuation.point-d-0.vulkan,Pass,0.025\n"
            "attenuation.point-d-half-range.vulkan,Fail,1.500\n"
            "limits.popping-64.vulkan,QualityWarning,0.320\n"
            "stability.far-1e6.vulkan,Crash,0.040\n"
            "attenuation.point-d-0.gl-egl-softpipe,Pass,0.082\n"
            "attenuation.point-d-half-range.gl-egl-softpipe,ExpectedFail,0.082\n"
            "limits.popping-64.gl-egl-softpipe,Timeout,120.000\n"
            "baked.legacy-falloff.gl-egl-softpipe,UnexpectedPass,0.092\n"
            "deferred.ldr8.gl-egl-softpipe,NotSupported,0.001\n"
            "per-object.eleven lights#1.gl-egl-softpipe,Fail,0.095\n");
}

TEST(RunCsv, FailuresListTheRunFailuresWithAReason) {
  EXPECT_EQ(failuresCsv(testing::records(testing::sampleResults())),
            "# failures.csv of the lightcts run started 2026-11-25T10:00:00Z (lightcts v0.1-42-gabc1234)\n"
            "# The run failures as expected failures: `lightcts run --expected-failures` reads this file\n"
            "# as it is. Copy it to seed a driver's list; replace each reason after '#' with the cause.\n"
            "attenuation.point-d-half-range.vulkan,Fail  # 37 failing of 4096 compared pixels, max error 0.25\n"
            "stability.far-1e6.vulkan,Crash  # worker crashed: signal 11 <SIGSEGV> & \"core\"\n"
            "limits.popping-64.gl-egl-softpipe,Timeout  # no result after 120 s\n"
            "# baked.legacy-falloff.gl-egl-softpipe,UnexpectedPass: passes now; remove its line from the "
            "expected-failures file (it was listed: softpipe lightmap filtering)\n"
            "# per-object.eleven lights#1.gl-egl-softpipe,Fail: cannot be listed, an expected-failures file "
            "cannot hold a name with ',' or '#'\n");
}

TEST(RunCsv, FailuresLoadBackAsExpectedFailures) {
  runner::ExpectedFailures expected;
  ASSERT_NO_THROW(expected.parse(failuresCsv(testing::records(testing::sampleResults())), "failures.csv"));
  const runner::ExpectedFailure* fail = expected.find("attenuation.point-d-half-range.vulkan");
  ASSERT_NE(fail, nullptr);
  EXPECT_EQ(fail->status, Verdict::Fail);
  EXPECT_EQ(fail->reason, "37 failing of 4096 compared pixels, max error 0.25");
  ASSERT_NE(expected.find("stability.far-1e6.vulkan"), nullptr);
  EXPECT_EQ(expected.find("stability.far-1e6.vulkan")->status, Verdict::Crash);
  ASSERT_NE(expected.find("limits.popping-64.gl-egl-softpipe"), nullptr);
  EXPECT_EQ(expected.find("limits.popping-64.gl-egl-softpipe")->status, Verdict::Timeout);
  // Neither passes nor the tests listed as comments become entries.
  EXPECT_EQ(expected.find("attenuation.point-d-0.vulkan"), nullptr);
  EXPECT_EQ(expected.find("baked.legacy-falloff.gl-egl-softpipe"), nullptr);
  EXPECT_EQ(expected.find("limits.popping-64.vulkan"), nullptr);  // a QualityWarning is no run failure
}

// Every run failure a run can have loads back, whatever its message holds.
TEST(RunCsv, MessagesWithCommasHashesAndLineBreaksStillLoad) {
  auto results = testing::sampleResults();
  results["tests"][0]["verdict"] = "Fail";
  results["tests"][0]["message"] = std::string("a, b # c\r\nsecond line\x07");
  results["tests"][1]["message"] = "\t \n";  // blank: the pixels instead
  results["tests"][2]["verdict"] = "Crash";
  results["tests"][2]["message"] = "";
  results["tests"][2]["metrics"] = nullptr;
  const std::string text = failuresCsv(testing::records(results));
  EXPECT_NE(text.find("attenuation.point-d-0.vulkan,Fail  # a, b # c\n"), std::string::npos) << text;
  EXPECT_NE(text.find("attenuation.point-d-half-range.vulkan,Fail  # 37 failing of 4096"), std::string::npos) << text;
  EXPECT_NE(text.find("limits.popping-64.vulkan,Crash  # Crash with no message\n"), std::string::npos) << text;
  runner::ExpectedFailures expected;
  ASSERT_NO_THROW(expected.parse(text, "failures.csv"));
  ASSERT_NE(expected.find("attenuation.point-d-0.vulkan"), nullptr);
  EXPECT_EQ(expected.find("attenuation.point-d-0.vulkan")->reason, "a, b # c");
}

TEST(RunCsv, UnknownVerdictsAreShownNotListed) {
  auto results = testing::sampleResults();
  results["tests"][0]["verdict"] = "pass";
  const std::string text = failuresCsv(testing::records(results));
  EXPECT_NE(text.find("# attenuation.point-d-0.vulkan,pass: unknown verdict, not listed\n"), std::string::npos) << text;
  EXPECT_NE(resultsCsv(testing::records(results)).find("attenuation.point-d-0.vulkan,pass,0.025\n"), std::string::npos);
}

// An interrupted run's NotRun test is a run failure, but no line an
// expected-failures file can hold: a comment, and the file still loads.
TEST(RunCsv, NotRunTestsAreShownNotListed) {
  auto results = testing::sampleResults();
  results["tests"][0]["verdict"] = "NotRun";
  results["tests"][0]["message"] = "not run: the run was interrupted by SIGINT first";
  const std::string text = failuresCsv(testing::records(results));
  EXPECT_NE(text.find("# attenuation.point-d-0.vulkan,NotRun: not run: the run was interrupted by SIGINT first; not "
                      "listed, an expected-failures line cannot name NotRun\n"),
            std::string::npos)
      << text;
  runner::ExpectedFailures expected;
  ASSERT_NO_THROW(expected.parse(text, "failures.csv"));
  EXPECT_EQ(expected.find("attenuation.point-d-0.vulkan"), nullptr);
}

TEST(RunCsv, NamesWithCommasAreQuotedInResults) {
  auto results = testing::sampleResults();
  results["tests"][0]["name"] = "a,b \"c\".vulkan";
  results["tests"][0]["verdict"] = "Fail";
  const std::string text = resultsCsv(testing::records(results));
  EXPECT_EQ(text.substr(0, text.find('\n')), "\"a,b \"\"c\"\".vulkan\",Fail,0.025");
  EXPECT_NE(failuresCsv(testing::records(results)).find("\n# a,b \"c\".vulkan,Fail: cannot be listed"), std::string::npos);
}

TEST(RunCsv, AnEmptyRunHasNoLines) { EXPECT_EQ(resultsCsv(results::RunRecord{}), ""); }

TEST(RunCsv, WritesBothFilesAtomically) {
  const fs::path dir = fs::path(::testing::TempDir()) / "reports_csv_test";
  fs::remove_all(dir);
  fs::create_directories(dir);
  writeRunCsvs(testing::records(testing::sampleResults()), dir);
  EXPECT_EQ(readFile(dir / "results.csv"), resultsCsv(testing::records(testing::sampleResults())));
  EXPECT_EQ(readFile(dir / "failures.csv"), failuresCsv(testing::records(testing::sampleResults())));
  long long entries = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir)) ++entries;
  EXPECT_EQ(entries, 2) << "no temporary file is left behind";
  runner::ExpectedFailures expected;
  EXPECT_NO_THROW(expected.load(dir / "failures.csv"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace reports
