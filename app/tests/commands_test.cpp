// The subcommands of SPEC 8 called as a library: output formats, files and
// exit statuses. Expected JSON is written out by hand from SPEC 5.
#include "app/commands.h"
#include "app/exit_status.h"
#include "imaging/image_files.h"
#include "imaging/tests/scratch_folder_test.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace app {
namespace {

namespace fs = std::filesystem;

class CommandsTest : public imaging::testing::ScratchFolderTest {
 protected:

  std::string writeScene(const std::string& json) {
    const std::string path = (dir_ / "scene.json").string();
    std::ofstream(path) << json;
    return path;
  }

  std::ostringstream out_, err_;
};

// Camera at (0, 10, 0) looking down (SPEC 2 defaults). Lights: 0 a point at
// distance^2 82 from the camera, 1 a directional, 2 a point at distance^2 100,
// 3 a baked light (no part), 4 a mixed shadowed point (channel 0).
const char* kSelectionScene = R"({
  "lightcts": 1, "image": {"width": 4, "height": 4},
  "camera": {"position": [0, 10, 0], "target": [0, 0, 0], "up": [0, 0, -1]},
  "pipeline": {"lights_per_object": true},
  "objects": [{"name": "floor", "mesh": {"type": "plane", "size": [2, 2]}}],
  "lights": [
    {"name": "near", "type": "point", "position": [1, 1, 0], "range": 3},
    {"name": "sun", "type": "directional", "direction": [0, -1, 0]},
    {"name": "far", "type": "point", "position": [0, 0, 0], "range": 3, "intensity": 9},
    {"name": "baked", "type": "point", "position": [0, 0, 0], "mode": "baked"},
    {"name": "mixed", "type": "point", "position": [0, 0.5, 0], "range": 1, "mode": "mixed", "shadows": true}
  ]
})";

TEST_F(CommandsTest, LightsPrintsTheSpecJson) {
  const std::string scene = writeScene(kSelectionScene);
  ASSERT_EQ(runLightsCommand({scene, 0}, false, out_, err_), kExitSuccess) << err_.str();
  const auto json = nlohmann::ordered_json::parse(out_.str());
  // Keys in SPEC order.
  std::vector<std::string> keys;
  for (const auto& item : json.items()) keys.push_back(item.key());
  EXPECT_EQ(keys, (std::vector<std::string>{"visible", "objects", "shadow_mask"}));
  // Directional first; then points by distance^2: mixed (90.25), near (82)?
  // near: 1 + 81 = 82; mixed: 9.5^2 = 90.25; far: 100.
  const auto expectedVisible = nlohmann::ordered_json::parse(R"([
    {"light": 1, "name": "sun", "packed": 0},
    {"light": 0, "name": "near", "packed": 0},
    {"light": 4, "name": "mixed", "packed": 1},
    {"light": 2, "name": "far", "packed": 2}])");
  EXPECT_EQ(json["visible"], expectedVisible);
  // Floor: centre (0, 0, 0), radius sqrt2. All three points touch it.
  // Importance: far 9 * 1 / 1e-5 (d = 0 clamps), mixed 1 * (1 - 0.0625)^2 / 0.25,
  // near 1 * rangeAtt(2/9) / 2: far, mixed, near -> packed 2, 1, 0.
  const auto expectedObjects = nlohmann::ordered_json::parse(R"([{"name": "floor", "count": 3, "indices": [2, 1, 0]}])");
  EXPECT_EQ(json["objects"], expectedObjects);
  const auto expectedMask = nlohmann::ordered_json::parse(R"([{"light": 4, "name": "mixed", "channel": 0, "demoted": false}])");
  EXPECT_EQ(json["shadow_mask"], expectedMask);
}

TEST_F(CommandsTest, ReferenceWritesExrAndPreview) {
  const std::string scene = writeScene(kSelectionScene);
  const std::string out = (dir_ / "ref").string();
  ASSERT_EQ(runReferenceCommand({scene, 0}, false, false, out, out_, err_), kExitSuccess) << err_.str();
  const imaging::Image value = imaging::readExr(out + "/reference.exr");
  const imaging::Image tolerance = imaging::readExr(out + "/tolerance.exr");
  EXPECT_EQ(value.channels, 4);  // RGB value, A mask
  EXPECT_EQ(tolerance.channels, 3);
  EXPECT_EQ(value.width, 4);
  EXPECT_EQ(value.height, 4);
  EXPECT_TRUE(fs::exists(out + "/reference.png"));
  // No temporary files are left behind.
  for (const auto& entry : fs::directory_iterator(out)) EXPECT_EQ(entry.path().filename().string().find(".partial"), std::string::npos);
}

// --tolerance-terms (docs/cli.md): the tolerance's two parts beside it, and
// only when asked.
TEST_F(CommandsTest, ReferenceWritesToleranceTermsOnlyWhenAsked) {
  const std::string scene = writeScene(kSelectionScene);
  const std::string plain = (dir_ / "plain").string(), terms = (dir_ / "terms").string();
  ASSERT_EQ(runReferenceCommand({scene, 0}, false, false, plain, out_, err_), kExitSuccess) << err_.str();
  EXPECT_FALSE(fs::exists(plain + "/tolerance-shift.exr"));
  ASSERT_EQ(runReferenceCommand({scene, 0}, false, true, terms, out_, err_), kExitSuccess) << err_.str();
  const imaging::Image tolerance = imaging::readExr(terms + "/tolerance.exr");
  const imaging::Image arithmetic = imaging::readExr(terms + "/tolerance-arithmetic.exr");
  const imaging::Image shift = imaging::readExr(terms + "/tolerance-shift.exr");
  ASSERT_EQ(arithmetic.pixels.size(), tolerance.pixels.size());
  ASSERT_EQ(shift.pixels.size(), tolerance.pixels.size());
  for (std::size_t k = 0; k < tolerance.pixels.size(); ++k)
    EXPECT_NEAR(double(arithmetic.pixels[k]) + shift.pixels[k], tolerance.pixels[k], 1e-6 * tolerance.pixels[k]);
}

TEST_F(CommandsTest, BadSceneExitsTwoNamingThePath) {
  std::string json = kSelectionScene;
  json.replace(json.find("\"range\": 3,"), 11, "\"range\": -3,");  // light 2, "far"
  const std::string scene = writeScene(json);
  EXPECT_EQ(runLightsCommand({scene, 0}, false, out_, err_), kExitBadInput);
  EXPECT_NE(err_.str().find("/lights/2/range"), std::string::npos) << err_.str();
  EXPECT_TRUE(out_.str().empty());  // nothing half-written on stdout
}

TEST_F(CommandsTest, BadSceneWritesNoReferenceFiles) {
  const std::string scene = writeScene("{\"lightcts\": 1}");
  const std::string out = (dir_ / "ref").string();
  EXPECT_EQ(runReferenceCommand({scene, 0}, false, false, out, out_, err_), kExitBadInput);
  EXPECT_FALSE(fs::exists(out + "/reference.exr"));
}

TEST_F(CommandsTest, FrameOutOfRangeExitsTwo) {
  const std::string scene = writeScene(kSelectionScene);
  EXPECT_EQ(runLightsCommand({scene, 1}, false, out_, err_), kExitBadInput);
  EXPECT_NE(err_.str().find("--frame 1 is out of range"), std::string::npos) << err_.str();
}

TEST_F(CommandsTest, MissingSceneFileExitsTwo) {
  EXPECT_EQ(runLightsCommand({(dir_ / "nope.json").string(), 0}, false, out_, err_), kExitBadInput);
  EXPECT_NE(err_.str().find("nope.json"), std::string::npos);
}

// (A device that is not here: app/tests/absent_device_test.cpp, which loads
// the drivers and so is labelled `driver`.)
TEST_F(CommandsTest, UnknownBackendExitsTwo) {
  const std::string scene = writeScene(kSelectionScene);
  EXPECT_EQ(runCompareCommand({scene, 0}, {.backend = "metal"}, "", true, out_, err_), kExitBadInput);
  EXPECT_NE(err_.str().find("unknown backend 'metal'"), std::string::npos);
}

TEST_F(CommandsTest, UnwritableOutputExitsTwo) {
  const std::string scene = writeScene(kSelectionScene);
  const std::string blocker = (dir_ / "file").string();
  std::ofstream(blocker) << "x";
  EXPECT_EQ(runReferenceCommand({scene, 0}, false, false, blocker + "/sub", out_, err_), kExitBadInput);
  EXPECT_NE(err_.str().find("cannot create output folder"), std::string::npos) << err_.str();
}

}  // namespace
// A hand-edited results.json with a key missing, given where lightcts reads
// a person's results.json: refused (exit 2) with the key's path, never a crash.
const char* kResultsWithoutATestsName = R"({"format": "lightcts-results", "version": 1,
  "backends": [{"backend": "vulkan", "status": "ran"}],
  "tests": [{"name": "g.a.vulkan", "backend": "vulkan", "verdict": "Pass"},
            {"backend": "vulkan", "verdict": "Pass", "timings_ms": {"total": 3}}]})";

TEST_F(CommandsTest, RunCompareRefusesAResultsFileWithAKeyMissing) {
  const std::string broken = (dir_ / "results.json").string();
  std::ofstream(broken) << kResultsWithoutATestsName;
  EXPECT_EQ(app::runRunCompareCommand(broken, broken, (dir_ / "page").string(), out_, err_), app::kExitBadInput);
  EXPECT_NE(err_.str().find(broken + ": tests[1].name is missing"), std::string::npos) << err_.str();
  EXPECT_FALSE(fs::exists(dir_ / "page"));
}

TEST_F(CommandsTest, RunTimingsRefusesAResultsFileWithAKeyMissing) {
  const std::string broken = (dir_ / "results.json").string();
  std::ofstream(broken) << kResultsWithoutATestsName;
  runner::RunOptions options;
  options.scenesDir = std::string(LIGHTCTS_SOURCE_DIR) + "/app/tests/scenes";
  options.backends = {"vulkan"};
  options.outDir = (dir_ / "run").string();
  options.shard = runner::ShardSpec{1, 2};
  options.timingsFile = broken;
  EXPECT_EQ(app::runSuiteCommand(options, out_, err_), app::kExitBadInput);
  EXPECT_NE(err_.str().find("--timings " + broken + ": tests[1].name is missing"), std::string::npos) << err_.str();
  EXPECT_FALSE(fs::exists(dir_ / "run"));
}

}  // namespace app
