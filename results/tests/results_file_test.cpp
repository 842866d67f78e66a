// results/results_file.h: a file written by RunRecord::toJson reads back; a
// hand-edited one with a key missing is refused with the key's path; what
// docs/results-format.md promises to tolerate is read.
#include "results/results_file.h"

#include "imaging/tests/scratch_folder_test.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace results {
namespace {

namespace fs = std::filesystem;
using comparison::Verdict;

RunRecord twoTestRun() {
  RunRecord run;
  run.lightctsRevision = "v1";
  BackendRecord backend;
  backend.backend = "vulkan";
  backend.status = comparison::BackendStatus::Ran;
  run.backends.push_back(backend);
  for (const char* name : {"g.a.vulkan", "g.b.vulkan"}) {
    TestRecord test;
    test.name = name;
    test.backend = "vulkan";
    test.verdict = test.rawVerdict = Verdict::Pass;
    test.timingsMs = StageTimes{1, 2, 3, 4, 5, 15};
    run.tests.push_back(test);
  }
  return run;
}

class ResultsFile : public imaging::testing::ScratchFolderTest {
 protected:
  void write(const Json& json) { std::ofstream(file()) << json.dump(1); }
  std::string refusal(const Json& json) {
    write(json);
    try {
      readResultsFile(file());
    } catch (const ResultsFileError& e) {
      return e.what();
    }
    return "(read)";
  }
  fs::path file() const { return dir_ / "results.json"; }
};

TEST_F(ResultsFile, WhatTheWriterWritesReadsBack) {
  write(twoTestRun().toJson());
  const RunRecord run = readResultsFile(file());
  ASSERT_EQ(run.tests.size(), 2u);
  EXPECT_EQ(run.tests[1].name, "g.b.vulkan");
  ASSERT_TRUE(run.tests[1].timingsMs.has_value());
  EXPECT_EQ(run.tests[1].timingsMs->draw, 3);
  EXPECT_EQ(run.tests[1].timingsMs->total, 15);
  EXPECT_EQ(run.backends[0].status, comparison::BackendStatus::Ran);
}

TEST_F(ResultsFile, AMissingKeyIsRefusedByItsPath) {
  const Json whole = twoTestRun().toJson();
  const std::pair<Json::json_pointer, std::string> cases[] = {
      {Json::json_pointer("/tests/1/name"), "tests[1].name is missing"},
      {Json::json_pointer("/tests/0/verdict"), "tests[0].verdict is missing"},
      {Json::json_pointer("/tests/0/backend"), "tests[0].backend is missing"},
      {Json::json_pointer("/backends/0/status"), "backends[0].status is missing"},
      {Json::json_pointer("/backends/0/backend"), "backends[0].backend is missing"},
      {Json::json_pointer("/tests"), ": tests is missing"},
      {Json::json_pointer("/backends"), ": backends is missing"},
      {Json::json_pointer("/format"), "not a lightcts results.json"}};
  for (const auto& [pointer, message] : cases) {
    Json edited = whole;
    edited[pointer.parent_pointer()].erase(pointer.back());
    const std::string said = refusal(edited);
    EXPECT_NE(said.find(message), std::string::npos) << pointer.to_string() << ": " << said;
    EXPECT_EQ(said.rfind(file().string(), 0), 0u) << said;  // the message starts with the file
  }
}

TEST_F(ResultsFile, AKeyOfAnotherTypeIsRefused) {
  Json edited = twoTestRun().toJson();
  edited["tests"][0]["name"] = 7;
  EXPECT_NE(refusal(edited).find("tests[0].name is not a string"), std::string::npos);
  edited = twoTestRun().toJson();
  edited["tests"][1] = "g.b.vulkan";
  EXPECT_NE(refusal(edited).find("tests[1] is not an object"), std::string::npos);
}

TEST_F(ResultsFile, NotJsonAndNoFileAreRefused) {
  std::ofstream(file()) << "{\"format\": ";
  EXPECT_THROW(readResultsFile(file()), ResultsFileError);
  EXPECT_THROW(readResultsFile(file().string() + ".absent"), ResultsFileError);
}

// docs/results-format.md: later versions' keys may be missing, words no
// verdict has are read, and keys lightcts does not know are passed over.
TEST_F(ResultsFile, OlderFilesUnknownWordsAndUnknownKeysAreRead) {
  Json edited = twoTestRun().toJson();
  for (Json& test : edited["tests"]) {
    test.erase("timings_ms");
    test.erase("raw_verdict");
    test["from_a_later_version"] = true;
  }
  edited["backends"][0].erase("task_ms");
  edited["backends"][0].erase("counts");
  edited.erase("slowest");
  edited.erase("mutants");
  edited["tests"][0]["verdict"] = "Maybe";
  write(edited);
  const RunRecord run = readResultsFile(file());
  EXPECT_FALSE(run.tests[1].timingsMs.has_value());
  EXPECT_TRUE(comparison::isRunFailure(run.tests[0].verdict));  // a word it does not know is no pass
}

}  // namespace
}  // namespace results
