// Test support for the runner's tests against runner/tests/mock_worker.cpp:
// a scratch folder per test, the mock's script written into it and named by
// LIGHTCTS_MOCK_SCRIPT for as long as the test runs.
#pragma once

#include "imaging/tests/scratch_folder_test.h"

#include <nlohmann/json.hpp>

#include <cstdlib>
#include <fstream>
#include <string>

namespace runner::testing {

class MockWorkerTest : public imaging::testing::ScratchFolderTest {
 protected:
  void TearDown() override {
    unsetenv("LIGHTCTS_MOCK_SCRIPT");
    ScratchFolderTest::TearDown();
  }

  // The script the mock worker follows (its grammar: mock_worker.cpp).
  void script(const nlohmann::ordered_json& json) {
    const std::string file = (dir_ / "mock-script.json").string();
    std::ofstream(file) << json.dump(1);
    setenv("LIGHTCTS_MOCK_SCRIPT", file.c_str(), 1);
  }

  // How many lines of the mock's counter file (mock-starts.txt,
  // mock-attempts.txt) are `what`.
  int counted(const std::string& file, const std::string& what) const {
    std::ifstream in(dir_ / file);
    int n = 0;
    for (std::string line; std::getline(in, line);) n += line == what;
    return n;
  }

  static constexpr const char* kMockWorker = LIGHTCTS_MOCK_WORKER;
};

}  // namespace runner::testing
