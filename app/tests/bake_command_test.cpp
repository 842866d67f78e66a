// `lightcts bake` called as a library: the files it writes, bake.json, the
// overlap PNG's colours, the cache, and its exit statuses (docs/cli.md).
#include "app/commands.h"
#include "app/exit_status.h"
#include "baking/bake.h"
#include "baking/overlap_map.h"
#include "imaging/image_files.h"
#include "imaging/tests/scratch_folder_test.h"
#include "scene_input/scene_loader.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace app {
namespace {

namespace fs = std::filesystem;

const std::string kSourceDir = LIGHTCTS_SOURCE_DIR;
// 8 x 8 floor, 32 x 32 map, five mixed shadowed lights around the centre
// (the fifth demoted), a baked light and a box.
const std::string kFiveOverlapping = kSourceDir + "/app/tests/scenes/bake-five-overlapping.json";

class BakeCommandTest : public imaging::testing::ScratchFolderTest {
 protected:
  void SetUp() override {
    ScratchFolderTest::SetUp();
    if (const char* saved = std::getenv("LIGHTCTS_CACHE_DIR")) savedCacheDir_ = saved;
    ::setenv("LIGHTCTS_CACHE_DIR", (dir_ / "cache").c_str(), 1);  // a cache of this test's own
  }
  void TearDown() override {
    if (savedCacheDir_) {
      ::setenv("LIGHTCTS_CACHE_DIR", savedCacheDir_->c_str(), 1);
    } else {
      ::unsetenv("LIGHTCTS_CACHE_DIR");
    }
    ScratchFolderTest::TearDown();
  }

  int bake(const std::string& scene, const std::string& out, bool noCache = false) {
    out_.str("");
    err_.str("");
    return runBakeCommand({scene, out, noCache}, out_, err_);
  }

  static nlohmann::json readJson(const fs::path& path) {
    std::ifstream in(path);
    return nlohmann::json::parse(in);
  }

  std::optional<std::string> savedCacheDir_;
  std::ostringstream out_, err_;
};

TEST_F(BakeCommandTest, WritesMapsOverlapAndBakeJson) {
  const fs::path out = dir_ / "out";
  ASSERT_EQ(bake(kFiveOverlapping, out.string()), kExitSuccess) << err_.str();
  for (const char* file : {"floor.lightmap.exr", "floor.shadowmask.exr", "floor.overlap.png", "bake.json"})
    EXPECT_TRUE(fs::is_regular_file(out / file)) << file;
  for (const auto& entry : fs::directory_iterator(out))
    EXPECT_EQ(entry.path().filename().string().find(".partial"), std::string::npos);

  const nlohmann::json json = readJson(out / "bake.json");
  EXPECT_EQ(json["scene"], "bake-five-overlapping");
  EXPECT_EQ(json["from_cache"], false);
  EXPECT_EQ(json["cache_key"].get<std::string>().size(), 64u);
  EXPECT_GE(json["bake_milliseconds"].get<double>(), 0.0);
  ASSERT_EQ(json["objects"].size(), 1u);
  const nlohmann::json& floor = json["objects"][0];
  EXPECT_EQ(floor["name"], "floor");
  EXPECT_EQ(floor["resolution"], 32);
  EXPECT_EQ(floor["max_overlap"], 5);
  EXPECT_GT(floor["texels_over_4"].get<long long>(), 0);
  // SPEC 5.3 order m0..m4 (luminance * range^2 falls with the intensity);
  // m4 overlaps all four holders and is demoted.
  ASSERT_EQ(json["shadow_mask"].size(), 5u);
  for (int k = 0; k < 4; ++k) {
    EXPECT_EQ(json["shadow_mask"][k]["light"], k);
    EXPECT_EQ(json["shadow_mask"][k]["channel"], k);
    EXPECT_EQ(json["shadow_mask"][k]["demoted"], false);
  }
  EXPECT_EQ(json["shadow_mask"][4]["name"], "m4-demoted");
  EXPECT_EQ(json["shadow_mask"][4]["demoted"], true);
  EXPECT_EQ(json["demoted"], nlohmann::json::array({"m4-demoted"}));

  // The EXRs hold exactly the baked texels.
  baking::BakeOptions noCache;
  noCache.useCache = false;
  const auto baked = baking::bakeScene(*lighting::prepareScene(scene_input::loadSceneFile(kFiveOverlapping)), noCache);
  const lighting::ObjectBake& maps = baked->objects[0];
  const imaging::Image lightmap = imaging::readExr((out / "floor.lightmap.exr").string());
  const imaging::Image mask = imaging::readExr((out / "floor.shadowmask.exr").string());
  ASSERT_EQ(lightmap.channels, 3);
  ASSERT_EQ(mask.channels, 4);
  ASSERT_EQ(lightmap.width, 32);
  ASSERT_EQ(lightmap.height, 32);
  for (int j = 0; j < 32; ++j)
    for (int i = 0; i < 32; ++i)
      for (int c = 0; c < 4; ++c) {
        const std::size_t t = (std::size_t(j) * 32 + std::size_t(i)) * 4 + std::size_t(c);
        if (c < 3) {
          EXPECT_EQ(lightmap.at(i, j, c), maps.lightmap.texels[t]);
        }
        EXPECT_EQ(mask.at(i, j, c), maps.shadowMask.texels[t]);
      }
  // The demoted light and the baked lamp light the floor's centre texel.
  EXPECT_GT(lightmap.at(16, 16, 0), 0.0f);

  // The overlap PNG: texel (i, j) is pixel (i, j). Texel (16, 16) at
  // (0.125, 0, 0.125) lies within range 3 of all five lights: red. Texel
  // (0, 0) at (-3.875, 0, -3.875) has d^2 = 2 * 2.875^2 + 1 = 17.5 > 3^2
  // to m0, the nearest: no light, the legend's 0.
  const imaging::Image png = imaging::readExr((out / "floor.overlap.png").string());
  ASSERT_EQ(png.width, 32);
  ASSERT_EQ(png.channels, 3);
  auto colourAt = [&](int i, int j) {
    baking::Rgb8 rgb;
    for (int c = 0; c < 3; ++c) rgb[std::size_t(c)] = std::uint8_t(std::lround(png.at(i, j, c) * 255));
    return rgb;
  };
  EXPECT_EQ(colourAt(16, 16), (baking::Rgb8{255, 0, 0}));
  EXPECT_EQ(colourAt(0, 0), baking::overlapColour(0));
  long long red = 0;
  for (int j = 0; j < 32; ++j)
    for (int i = 0; i < 32; ++i) red += colourAt(i, j) == baking::Rgb8{255, 0, 0};
  EXPECT_EQ(red, floor["texels_over_4"].get<long long>());
}

TEST_F(BakeCommandTest, SecondRunReadsTheCacheAndNoCacheBakes) {
  ASSERT_EQ(bake(kFiveOverlapping, (dir_ / "a").string()), kExitSuccess) << err_.str();
  ASSERT_EQ(bake(kFiveOverlapping, (dir_ / "b").string()), kExitSuccess) << err_.str();
  EXPECT_NE(out_.str().find("read from the cache"), std::string::npos) << out_.str();
  const nlohmann::json a = readJson(dir_ / "a" / "bake.json"), b = readJson(dir_ / "b" / "bake.json");
  EXPECT_EQ(b["from_cache"], true);
  EXPECT_EQ(b["cache_key"], a["cache_key"]);
  ASSERT_EQ(bake(kFiveOverlapping, (dir_ / "c").string(), true), kExitSuccess) << err_.str();
  EXPECT_EQ(readJson(dir_ / "c" / "bake.json")["from_cache"], false);
}

TEST_F(BakeCommandTest, SceneWithoutLightmapsExitsTwo) {
  const fs::path scene = dir_ / "plain.json";
  std::ofstream(scene) << R"({"lightcts": 1, "image": {"width": 4, "height": 4}, "camera": {},
    "objects": [{"name": "floor", "mesh": {"type": "plane"}, "static": true}], "lights": []})";
  EXPECT_EQ(bake(scene.string(), (dir_ / "out").string()), kExitBadInput);
  EXPECT_NE(err_.str().find("nothing to bake"), std::string::npos) << err_.str();
  EXPECT_FALSE(fs::exists(dir_ / "out"));
}

TEST_F(BakeCommandTest, BadSceneExitsTwoAndWritesNothing) {
  const fs::path scene = dir_ / "bad.json";
  std::ofstream(scene) << R"({"lightcts": 1, "image": {"width": 4, "height": 4}, "camera": {},
    "objects": [{"name": "floor", "mesh": {"type": "plane"}, "static": true, "lightmap_resolution": 8}],
    "lights": [{"type": "point", "range": -1}]})";
  EXPECT_EQ(bake(scene.string(), (dir_ / "out").string()), kExitBadInput);
  EXPECT_NE(err_.str().find("/lights/0/range"), std::string::npos) << err_.str();
  EXPECT_FALSE(fs::exists(dir_ / "out"));
  EXPECT_EQ(bake((dir_ / "missing.json").string(), (dir_ / "out").string()), kExitBadInput);
}

TEST_F(BakeCommandTest, UnwritableOutputExitsTwo) {
  std::ofstream(dir_ / "file") << "x";
  EXPECT_EQ(bake(kFiveOverlapping, (dir_ / "file" / "sub").string()), kExitBadInput);
  EXPECT_NE(err_.str().find("cannot create output folder"), std::string::npos) << err_.str();
}

// Objects named "a", "a-2", "a": the third may not take "a-2" (the second's
// name); every object gets files of its own.
TEST_F(BakeCommandTest, RepeatedNamesNeverShareFiles) {
  nlohmann::json scene = {{"lightcts", 1}, {"image", {{"width", 8}, {"height", 8}}},
                          {"camera", nlohmann::json::object()}, {"objects", nlohmann::json::array()},
                          {"lights", {{{"name", "bulb"}, {"type", "point"}, {"position", {0, 1, 0}}, {"range", 3},
                                       {"mode", "baked"}}}}};
  for (const char* name : {"a", "a-2", "a"})
    scene["objects"].push_back({{"name", name},
                                {"mesh", {{"type", "plane"}, {"size", {1, 1}}}},
                                {"static", true},
                                {"lightmap_resolution", 2}});
  const fs::path file = dir_ / "names.json";
  std::ofstream(file) << scene.dump(2);
  ASSERT_EQ(bake(file.string(), (dir_ / "out").string()), kExitSuccess) << err_.str();
  const nlohmann::json json = readJson(dir_ / "out" / "bake.json");
  std::set<std::string> lightmaps;
  for (const auto& object : json["objects"]) lightmaps.insert(object["lightmap"].get<std::string>());
  EXPECT_EQ(lightmaps.size(), 3u) << json.dump(1);
}

// The suite's demoted-fifth-light scene (suite/scenes/shadowmask/), whose
// lightmapped floor is reached at its centre by five mixed lights.
TEST_F(BakeCommandTest, SuiteFifthOverlappingSceneShowsTheConflict) {
  const std::string scene = kSourceDir + "/suite/scenes/shadowmask/fifth-overlapping-demoted.json";
  ASSERT_TRUE(lighting::prepareScene(scene_input::loadSceneFile(scene))->needsBake()) << scene << " lost its lightmap";
  ASSERT_EQ(bake(scene, (dir_ / "out").string()), kExitSuccess) << err_.str();
  const nlohmann::json json = readJson(dir_ / "out" / "bake.json");
  long long conflicts = 0;
  for (const auto& object : json["objects"]) conflicts += object["texels_over_4"].get<long long>();
  EXPECT_GT(conflicts, 0);
  EXPECT_FALSE(json["demoted"].empty());
}

}  // namespace
}  // namespace app
