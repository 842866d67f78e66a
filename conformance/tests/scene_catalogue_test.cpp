#include "conformance/scene_catalogue.h"

#include "imaging/tests/scratch_folder_test.h"

#include <gtest/gtest.h>

#include <fstream>
#include <unistd.h>

namespace conformance {
namespace {

namespace fs = std::filesystem;

class SceneCatalogue : public imaging::testing::ScratchFolderTest {
 protected:
  void SetUp() override {
    ScratchFolderTest::SetUp();
    for (const char* file : {"limits/b.json", "limits/a.json", "attenuation/z.json", "attenuation/notes.md"}) {
      fs::create_directories((dir_ / file).parent_path());
      std::ofstream(dir_ / file) << "{}";
    }
  }
};

TEST_F(SceneCatalogue, SuiteFolderGivesGroupsAndNamesSorted) {
  const auto scenes = findSceneFiles(dir_);
  ASSERT_EQ(scenes.size(), 3u);
  EXPECT_EQ(scenes[0].caseName(), "attenuation.z");
  EXPECT_EQ(scenes[1].caseName(), "limits.a");
  EXPECT_EQ(scenes[2].caseName(), "limits.b");
}

TEST_F(SceneCatalogue, GroupFolderIsOneGroupEvenWithATrailingSlash) {
  const auto scenes = findSceneFiles(dir_.string() + "/limits/");
  ASSERT_EQ(scenes.size(), 2u);
  EXPECT_EQ(scenes[0].caseName(), "limits.a");
}

TEST_F(SceneCatalogue, FolderWithoutScenesIsAnError) {
  fs::create_directories(dir_ / "empty");
  EXPECT_THROW(findSceneFiles(dir_ / "empty"), std::runtime_error);
  EXPECT_THROW(findSceneFiles(dir_ / "missing"), std::runtime_error);
}

}  // namespace
}  // namespace conformance
