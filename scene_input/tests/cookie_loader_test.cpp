// SPEC 2's `cookie` (SPEC 3.10): the loader reads the images, relative to the
// scene file, and refuses bad ones with the JSON path and the file.
#include "imaging/image_files.h"
#include "imaging/tests/scratch_folder_test.h"
#include "scene_input/scene_loader.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <unistd.h>
#include <vector>

namespace scene_input {
namespace {

using namespace lighting;

namespace fs = std::filesystem;

class CookieLoader : public imaging::testing::ScratchFolderTest {
 protected:
  void SetUp() override {
    ScratchFolderTest::SetUp();
    fs::create_directories(dir_ / "images");
    // 2x2 RGBA: alpha 0, 85, 170, 255 (n / 255), red 255 everywhere.
    imaging::writePng8((dir_ / "images/alpha.png").string(), 2, 2, 4,
                       {255, 0, 0, 0, 255, 0, 0, 85, 255, 0, 0, 170, 255, 0, 0, 255});
    // 3x2 RGB without alpha: the first channel is the cookie.
    imaging::writePng8((dir_ / "images/rgb.png").string(), 3, 2, 3,
                       {10, 1, 1, 20, 1, 1, 30, 1, 1, 40, 1, 1, 50, 1, 1, 60, 1, 1});
    imaging::writePng8((dir_ / "images/face4.png").string(), 4, 4, 1, std::vector<std::uint8_t>(16, 128));
    imaging::writePng8((dir_ / "images/face2.png").string(), 2, 2, 1, std::vector<std::uint8_t>(4, 128));
  }

  // A scene with one light around `light`, as if read from dir_/scene.json.
  Scene load(const std::string& light) const { return loadSceneText(text(light), (dir_ / "scene.json").string()); }
  std::string text(const std::string& light) const {
    return "{\"lightcts\": 1, \"image\": {}, \"camera\": {}, \"objects\": [],\n \"lights\": [" + light + "]}";
  }
  SceneError error(const std::string& light) const {
    try {
      load(light);
    } catch (const SceneLoadError& e) {
      return e.error();
    }
    ADD_FAILURE() << "loaded: " << light;
    return {};
  }
};

TEST_F(CookieLoader, DirectionalSpotAndPointCookiesLoadTheirImages) {
  const Scene d = load(R"({"type": "directional", "cookie": {"image": "images/alpha.png", "size": [2, 3]}})");
  ASSERT_TRUE(d.lights[0].cookie);
  const Cookie& c = *d.lights[0].cookie;
  EXPECT_EQ(c.sizeX, 2.0);
  EXPECT_EQ(c.sizeY, 3.0);
  ASSERT_EQ(c.images.size(), 1u);
  EXPECT_EQ(fs::path(c.files[0]), dir_ / "images/alpha.png");
  // The alpha channel, row 0 first, n / 255.
  EXPECT_FLOAT_EQ(c.images[0]->at(0, 0), 0.0f);
  EXPECT_FLOAT_EQ(c.images[0]->at(1, 0), 85.0f / 255.0f);
  EXPECT_FLOAT_EQ(c.images[0]->at(0, 1), 170.0f / 255.0f);
  EXPECT_FLOAT_EQ(c.images[0]->at(1, 1), 1.0f);

  const Scene s = load(R"({"type": "spot", "spot_angle_deg": 170, "cookie": {"image": "images/rgb.png"}})");
  const CookieImage& rgb = *s.lights[0].cookie->images[0];
  EXPECT_EQ(rgb.width, 3);
  EXPECT_EQ(rgb.height, 2);
  EXPECT_FLOAT_EQ(rgb.at(2, 1), 60.0f / 255.0f);  // no alpha: the first channel

  const std::string face = "\"images/face4.png\"";
  const Scene p = load(R"({"type": "point", "cookie": {"cube": [)" + face + ", " + face + ", " + face + ", " + face +
                       ", " + face + ", " + face + "]}}");
  EXPECT_EQ(p.lights[0].cookie->images.size(), 6u);
}

TEST_F(CookieLoader, BadCookiesNameTheirPathAndFile) {
  SceneError e = error(R"({"type": "spot", "cookie": {"image": "images/none.png"}})");
  EXPECT_EQ(e.jsonPath, "/lights/0/cookie/image");
  EXPECT_NE(e.message.find((dir_ / "images/none.png").string()), std::string::npos) << e.message;

  e = error(R"({"type": "spot", "mode": "mixed", "cookie": {"image": "images/rgb.png"}})");
  EXPECT_EQ(e.jsonPath, "/lights/0/cookie");
  EXPECT_NE(e.message.find("realtime"), std::string::npos) << e.message;

  e = error(R"({"type": "spot", "spot_angle_deg": 171, "cookie": {"image": "images/rgb.png"}})");
  EXPECT_EQ(e.jsonPath, "/lights/0/cookie");
  EXPECT_NE(e.message.find("170"), std::string::npos) << e.message;

  e = error(R"({"type": "spot", "cookie": {"cube": []}})");
  EXPECT_EQ(e.jsonPath, "/lights/0/cookie/cube");
  EXPECT_NE(e.message.find("does not apply to a spot light's cookie"), std::string::npos) << e.message;

  e = error(R"({"type": "directional", "cookie": {"image": "images/rgb.png"}})");
  EXPECT_NE(e.message.find("size"), std::string::npos) << e.message;

  const std::string four = "\"images/face4.png\"";
  e = error(R"({"type": "point", "cookie": {"cube": [)" + four + ", " + four + "]}}");
  EXPECT_EQ(e.jsonPath, "/lights/0/cookie/cube");
  EXPECT_NE(e.message.find("six faces"), std::string::npos) << e.message;

  e = error(R"({"type": "point", "cookie": {"cube": ["images/rgb.png", )" + four + ", " + four + ", " + four + ", " +
            four + ", " + four + "]}}");
  EXPECT_EQ(e.jsonPath, "/lights/0/cookie/cube/0");
  EXPECT_NE(e.message.find("square"), std::string::npos) << e.message;

  e = error(R"({"type": "point", "cookie": {"cube": [)" + four + ", " + four + ", \"images/face2.png\", " + four +
            ", " + four + ", " + four + "]}}");
  EXPECT_EQ(e.jsonPath, "/lights/0/cookie/cube/2");
  EXPECT_NE(e.message.find("equal"), std::string::npos) << e.message;
}

}  // namespace
}  // namespace scene_input
