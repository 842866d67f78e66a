#include "conformance/scene_catalogue.h"

#include <gtest/gtest.h>

#include <fstream>
#include <unistd.h>

namespace conformance {
namespace {

namespace fs = std::filesystem;

class SceneCatalogue : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() / ("lightcts-catalogue-" + std::to_string(::getpid()));
    fs::remove_all(root_);
    for (const char* file : {"limits/b.json", "limits/a.json", "attenuation/z.json", "attenuation/notes.md"}) {
      fs::create_directories((root_ / file).parent_path());
      std::ofstream(root_ / file) << "{}";
    }
  }
  void TearDown() override { fs::remove_all(root_); }
  fs::path root_;
};

TEST_F(SceneCatalogue, SuiteFolderGivesGroupsAndNamesSorted) {
  const auto scenes = findSceneFiles(root_);
  ASSERT_EQ(scenes.size(), 3u);
  EXPECT_EQ(scenes[0].caseName(), "attenuation.z");
  EXPECT_EQ(scenes[1].caseName(), "limits.a");
  EXPECT_EQ(scenes[2].caseName(), "limits.b");
}

TEST_F(SceneCatalogue, GroupFolderIsOneGroupEvenWithATrailingSlash) {
  const auto scenes = findSceneFiles(root_.string() + "/limits/");
  ASSERT_EQ(scenes.size(), 2u);
  EXPECT_EQ(scenes[0].caseName(), "limits.a");
}

TEST_F(SceneCatalogue, FolderWithoutScenesIsAnError) {
  fs::create_directories(root_ / "empty");
  EXPECT_THROW(findSceneFiles(root_ / "empty"), std::runtime_error);
  EXPECT_THROW(findSceneFiles(root_ / "missing"), std::runtime_error);
}

}  // namespace
}  // namespace conformance
