// `lightcts budget` (SPEC 5.5) as a library call: the files it writes, the
// maps' pixels against the counts (each count's bin colour, the scale fixed
// by SPEC: 0, 1, 2, 4, 8, 16, 32, 64+), the JSON's per-light reasons, every
// frame of an animated scene, and bad input.
#include "app/commands.h"
#include "app/exit_status.h"
#include "imaging/image_files.h"
#include "imaging/tests/scratch_folder_test.h"
#include "lighting/frame.h"
#include "reference/light_budget.h"
#include "reports/budget_maps.h"
#include "scene_input/scene_loader.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace app {
namespace {

using reports::countBin;
using reports::countBinColour;

namespace fs = std::filesystem;
const fs::path kScenes = fs::path(LIGHTCTS_SOURCE_DIR) / "suite/scenes";

// The command creates the output folder: it does not exist when a test starts.
class BudgetCommand : public imaging::testing::ScratchFolderTest {
 protected:
  BudgetCommand() : ScratchFolderTest(false) {}

  int run(const std::string& scene, int frame, bool frameGiven, bool allFrames) {
    SceneArguments args;
    args.scenePath = (kScenes / scene).string();
    args.frame = frame;
    args.frameGiven = frameGiven;
    return runBudgetCommand(args, allFrames, dir_.string(), out_, err_);
  }

  std::ostringstream out_, err_;
};

std::vector<std::uint8_t> readPng(const fs::path& path, int& width, int& height) {
  const imaging::Image8 image = imaging::readImage8(path.string());
  width = image.width;
  height = image.height;
  EXPECT_EQ(image.channels, 3) << path;
  return image.levels;
}

nlohmann::json readJson(const fs::path& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

TEST(BudgetMaps, CountBinsFollowTheFixedScale) {
  const std::pair<int, int> expected[] = {{0, 0},  {1, 1},  {2, 2},  {3, 2},  {4, 3},  {7, 3},  {8, 4},
                                          {15, 4}, {16, 5}, {31, 5}, {32, 6}, {63, 6}, {64, 7}, {500, 7}};
  for (const auto& [count, bin] : expected) EXPECT_EQ(countBin(count), bin) << count;
}

TEST_F(BudgetCommand, ElevenLightsMapsAndJsonMatchTheCounts) {
  ASSERT_EQ(run("per-object/eleven-lights.json", 0, false, false), kExitSuccess) << err_.str();
  for (const char* file : {"budget.json", "reach.png", "kept.png", "loss.exr", "loss.png"})
    EXPECT_TRUE(fs::exists(dir_ / file)) << file;
  // The counts the maps must show (reference/tests/light_budget_test.cpp
  // checks them against hand-derived ones).
  const auto prepared = lighting::prepareScene(scene_input::loadSceneFile((kScenes / "per-object/eleven-lights.json").string()));
  const reference::ReferenceRenderer renderer(prepared);
  const reference::LightBudget budget = reference::computeLightBudget(renderer, lighting::prepareFrame(prepared, 0));
  for (const auto& [file, counts] : {std::pair{"reach.png", &budget.reach}, std::pair{"kept.png", &budget.kept}}) {
    int width = 0, height = 0;
    const std::vector<std::uint8_t> rgb = readPng(dir_ / file, width, height);
    ASSERT_GE(width, budget.width);
    ASSERT_GE(height, budget.height + 10);  // the legend below
    for (int y = 0; y < budget.height; ++y)
      for (int x = 0; x < budget.width; ++x) {
        std::uint8_t want[3];
        countBinColour(countBin((*counts)[std::size_t(y) * budget.width + x]), want);
        const std::uint8_t* got = &rgb[(std::size_t(y) * width + x) * 3];
        ASSERT_TRUE(got[0] == want[0] && got[1] == want[1] && got[2] == want[2]) << file << " " << x << ", " << y;
      }
  }
  const nlohmann::json json = readJson(dir_ / "budget.json");
  ASSERT_EQ(json["frames"].size(), 1u);
  const nlohmann::json& frame = json["frames"][0];
  EXPECT_GT(frame["pixels_cut"].get<int>(), 0);
  EXPECT_TRUE(frame["popping_score"].is_null());
  // p0, p1, p2 are lost to the floor's 8 (the object), never to the frame.
  for (const nlohmann::json& light : frame["lights"]) {
    const std::string name = light["name"];
    const bool dropped = name == "p0" || name == "p1" || name == "p2";
    EXPECT_EQ(light["not_kept_because"]["frame"].get<int>(), 0) << name;
    EXPECT_EQ(light["not_kept_because"]["object"].get<long long>(),
              dropped ? light["reach_pixels"].get<long long>() : 0)
        << name;
    EXPECT_EQ(light["kept_pixels"].get<long long>(), dropped ? 0 : light["reach_pixels"].get<long long>()) << name;
  }
}

TEST_F(BudgetCommand, EveryFrameOfAnAnimatedSceneWithItsPoppingScore) {
  ASSERT_EQ(run("limits/popping-64.json", 0, false, true), kExitSuccess) << err_.str();
  const nlohmann::json json = readJson(dir_ / "budget.json");
  ASSERT_EQ(json["frames"].size(), 7u);
  for (int f = 0; f < 7; ++f) {
    EXPECT_TRUE(fs::exists(dir_ / ("frame-" + std::to_string(f)) / "kept.png")) << f;
    EXPECT_EQ(json["frames"][std::size_t(f)]["popping_score"].is_null(), f == 0) << f;
    if (f > 0) {
      EXPECT_GT(json["frames"][std::size_t(f)]["popping_score"].get<double>(), 0) << f;
    }
  }
  int width = 0, height = 0;
  readPng(dir_ / "kept-strip.png", width, height);
  EXPECT_GE(width, 7 * 96);  // seven 96-pixel maps side by side
}

TEST_F(BudgetCommand, AnAnimatedSceneGivesEveryFrameUnlessOneIsPicked) {
  // SPEC 5.5: without --frame, every frame of a camera path.
  ASSERT_EQ(run("limits/popping-64.json", 0, false, false), kExitSuccess) << err_.str();
  EXPECT_EQ(readJson(dir_ / "budget.json")["frames"].size(), 7u);
  EXPECT_TRUE(fs::exists(dir_ / "frame-6" / "kept.png"));
  fs::remove_all(dir_);
  ASSERT_EQ(run("limits/popping-64.json", 3, true, false), kExitSuccess) << err_.str();
  const nlohmann::json json = readJson(dir_ / "budget.json");
  ASSERT_EQ(json["frames"].size(), 1u);
  EXPECT_EQ(json["frames"][0]["frame"].get<int>(), 3);
  EXPECT_TRUE(fs::exists(dir_ / "kept.png"));
}

TEST_F(BudgetCommand, BadInputExitsTwo) {
  EXPECT_EQ(run("limits/popping-64.json", 7, true, false), kExitBadInput);  // frames 0..6
  EXPECT_NE(err_.str().find("--frame 7 is out of range"), std::string::npos) << err_.str();
  EXPECT_EQ(run("limits/popping-64.json", 1, true, true), kExitBadInput);   // --frame with --all-frames
  EXPECT_EQ(run("no-such-group/no-such-scene.json", 0, false, false), kExitBadInput);
  EXPECT_FALSE(fs::exists(dir_ / "budget.json"));  // nothing half-written
}

}  // namespace
}  // namespace app
