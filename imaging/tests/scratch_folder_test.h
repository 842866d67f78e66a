// The tests' scratch folder: a gtest fixture with a folder per test (unique
// to the process, the suite and the test, a parameterised test's "/"
// flattened), removed before and after the test, so a test sees exactly what
// it and the code under it write there; the file writers' tests look at what
// a write leaves in it.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace imaging::testing {

class ScratchFolderTest : public ::testing::Test {
 protected:
  // `create`: the folder exists when the test starts; false for a test
  // whose code under test must create it (or must not).
  explicit ScratchFolderTest(bool create = true) : create_(create) {}

  void SetUp() override {
    const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = std::string(test->test_suite_name()) + "." + test->name();
    std::replace(name.begin(), name.end(), '/', '-');
    dir_ = std::filesystem::temp_directory_path() / ("lightcts-" + std::to_string(::getpid()) + "-" + name);
    std::filesystem::remove_all(dir_);
    if (create_) std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  // The names in the folder, sorted.
  std::vector<std::string> namesInFolder() const {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(dir_))
      names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }

  std::filesystem::path dir_;

 private:
  bool create_;
};

// A file's bytes as text; "" when it cannot be read.
inline std::string readFile(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace imaging::testing
