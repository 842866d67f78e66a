#include "runner/evidence_limit.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

namespace runner {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

class EvidenceLimit : public ::testing::Test {
 protected:
  void SetUp() override {
    // A folder of its own: ctest runs this fixture's tests in parallel
    // processes, and another checkout's tests may run beside them.
    out_ = fs::path(::testing::TempDir()) /
           ("lightcts-evidence-limit-" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) +
            "-" + std::to_string(::getpid()));
    fs::remove_all(out_);
  }
  void TearDown() override { fs::remove_all(out_); }

  // A test record with an evidence folder of three files, as a worker leaves it.
  Json record(const std::string& name, const std::string& verdict) {
    const std::string dir = "evidence/" + name;
    fs::create_directories(out_ / dir);
    for (const char* file : {"result.exr", "viewer-data.js", "summary.json"}) std::ofstream(out_ / dir / file) << "x";
    return {{"name", name},
            {"verdict", verdict},
            {"evidence",
             {{"frame", 2}, {"viewer", dir + "/viewer.html"}, {"summary_json", dir + "/summary.json"}}}};
  }
  fs::path out_;
};

std::vector<results::TestRecord> records(const Json& tests) {
  std::vector<results::TestRecord> typed;
  for (const Json& t : tests) typed.push_back(results::TestRecord::fromJson(t));
  return typed;
}

TEST_F(EvidenceLimit, RunFailuresFirstThenTheRestLoseTheirImagesButKeepTheirNumbers) {
  // In test order: an expected failure, two failures, a pass without evidence.
  std::vector<results::TestRecord> tests = records(Json::array({record("a.expected.vulkan", "ExpectedFail"), record("b.fail.vulkan", "Fail"),
                            record("c.crash.vulkan", "Fail"), {{"name", "d.pass.vulkan"}, {"verdict", "Pass"},
                                                               {"evidence", nullptr}}}));
  EXPECT_EQ(limitEvidenceImages(tests, out_, 1), 2);
  // The first run failure keeps everything.
  EXPECT_TRUE(fs::exists(out_ / "evidence/b.fail.vulkan/result.exr"));
  EXPECT_EQ(tests[1].evidence->viewer, "evidence/b.fail.vulkan/viewer.html");
  // The second failure and the expected failure keep summary.json alone.
  for (const std::string name : {"c.crash.vulkan", "a.expected.vulkan"}) {
    EXPECT_FALSE(fs::exists(out_ / "evidence" / name / "result.exr")) << name;
    EXPECT_FALSE(fs::exists(out_ / "evidence" / name / "viewer-data.js")) << name;
    EXPECT_TRUE(fs::exists(out_ / "evidence" / name / "summary.json")) << name;
  }
  EXPECT_EQ(tests[2].evidence->toJson(), (Json{{"frame", 2}, {"summary_json", "evidence/c.crash.vulkan/summary.json"},
                                                {"images_kept", false}}));
  EXPECT_FALSE(tests[0].evidence->imagesKept);
  // Nothing of the record links to an image that went (the reports read the record itself).
  EXPECT_TRUE(tests[2].evidence->viewer.empty());
  EXPECT_TRUE(tests[2].evidence->errorMaskPng.empty());
  EXPECT_FALSE(tests[3].evidence.has_value());
}

TEST_F(EvidenceLimit, ALimitAboveTheFailuresKeepsEverything) {
  std::vector<results::TestRecord> tests = records(Json::array({record("b.fail.vulkan", "Fail")}));
  EXPECT_EQ(limitEvidenceImages(tests, out_, 50), 0);
  EXPECT_TRUE(fs::exists(out_ / "evidence/b.fail.vulkan/result.exr"));
}

TEST_F(EvidenceLimit, ASummaryPathOutsideTheEvidenceFolderRemovesNothing) {
  std::vector<results::TestRecord> tests = records(Json::array({record("b.fail.vulkan", "Fail")}));
  tests[0].evidence->summaryJson = "evidence/../summary.json";  // would name the run folder itself
  std::ofstream(out_ / "results.json") << "{}";
  EXPECT_EQ(limitEvidenceImages(tests, out_, 0), 1);
  EXPECT_TRUE(fs::exists(out_ / "results.json"));
  EXPECT_TRUE(fs::exists(out_ / "evidence/b.fail.vulkan/result.exr"));
}

TEST_F(EvidenceLimit, EvidenceWithoutASummaryRemovesNothingOutsideItsFolder) {
  std::vector<results::TestRecord> tests = records(Json::array({record("b.fail.vulkan", "Fail"),
                            {{"name", "e.odd.vulkan"}, {"verdict", "Fail"}, {"evidence", {{"frame", 0}}}}}));
  std::ofstream(out_ / "results.json") << "{}";
  EXPECT_EQ(limitEvidenceImages(tests, out_, 0), 2);
  EXPECT_TRUE(fs::exists(out_ / "results.json"));
  EXPECT_TRUE(fs::exists(out_ / "evidence/b.fail.vulkan/summary.json"));
}

}  // namespace
}  // namespace runner
