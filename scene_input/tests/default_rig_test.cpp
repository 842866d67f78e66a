// SPEC 2.1's default rig (lighting/default_rig.h): every light reaches the
// content, checked with the model's own formulas written out here (SPEC 3.2,
// 3.3) at every corner of the bounds; glTF files without lights get it, files
// with lights keep theirs, and an import may ask for it.
#include "lighting/default_rig.h"
#include "scene_input/gltf_scene_json.h"
#include "scene_input/scene_loader.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <tuple>

#include <unistd.h>

namespace scene_input {
namespace {

using namespace lighting;

const std::string kModels = std::string(LIGHTCTS_SOURCE_DIR) + "/suite/scenes/gltf/models/";

std::vector<Vec3> corners(const Vec3& lo, const Vec3& hi) {
  std::vector<Vec3> out;
  for (int i = 0; i < 8; ++i) out.push_back(Vec3(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z));
  return out;
}

Camera lookingFrom(const Vec3& position) {
  Camera camera;
  camera.position = position;
  camera.target = Vec3(0, 0, 0);
  camera.up = Vec3(0, 1, 0);
  camera.projection = Projection::Perspective;
  return camera;
}

// SPEC 3.2's rangeAtt and 3.3's spotAtt at point p, by hand.
double rangeAttenuation(const Light& light, const Vec3& p) {
  const Vec3 ray = light.position - p;
  const double distSqr = std::max(glm::dot(ray, ray), 1e-5);
  const double x = distSqr / std::max(light.range * light.range, 1e-5);
  const double window = std::clamp(1 - x * x, 0.0, 1.0);
  return window * window;
}

double spotAttenuation(const Light& light, const Vec3& p) {
  const double cosOuter = std::cos(light.spotAngleDeg / 2 * std::numbers::pi / 180);
  const double cosInner = std::cos(*light.innerSpotAngleDeg / 2 * std::numbers::pi / 180);
  const double a = 1 / std::max(cosInner - cosOuter, 0.001), b = -cosOuter * a;
  const Vec3 L = glm::normalize(light.position - p);
  const double s = std::clamp(glm::dot(-light.direction, L) * a + b, 0.0, 1.0);
  return s * s;
}

TEST(DefaultRig, ADirectionalAPointAndASpotThatEachReachEveryCorner) {
  for (const auto& [lo, hi, eye] :
       {std::tuple{Vec3(-1, -1, -1), Vec3(1, 1, 1), Vec3(2, 2, 5)},
        std::tuple{Vec3(-500, 0, -20), Vec3(500, 3, 20), Vec3(0, 50, 900)},
        std::tuple{Vec3(1e-4, 1e-4, 1e-4), Vec3(2e-4, 2e-4, 2e-4), Vec3(0, 0, 1)}}) {
    const DefaultRig rig = defaultRig(lo, hi, lookingFrom(eye));
    ASSERT_EQ(rig.lights.size(), 3u);
    EXPECT_EQ(rig.lights[0].type, LightType::Directional);
    EXPECT_EQ(rig.lights[1].type, LightType::Point);
    EXPECT_EQ(rig.lights[2].type, LightType::Spot);
    // The directional light travels downwards and away from the camera: it
    // lights what faces up and what faces the camera.
    EXPECT_LT(rig.lights[0].direction.y, 0);
    EXPECT_GT(glm::dot(rig.lights[0].direction, glm::normalize(Vec3(0) - eye)), 0);
    for (const Vec3& corner : corners(lo, hi)) {
      for (const Light* light : {&rig.lights[1], &rig.lights[2]}) {
        EXPECT_GT(rangeAttenuation(*light, corner), 0.1) << light->name << " at a corner of " << glm::length(hi - lo);
        EXPECT_GT(light->intensity, 0);
      }
      EXPECT_GT(spotAttenuation(rig.lights[2], corner), 0) << "the spot's cone misses a corner";
    }
    EXPECT_GT(rig.ambient.x, 0);
    EXPECT_LE(rig.ambient.x, 0.05);  // small: the lights, not the ambient, light the content
  }
}

TEST(DefaultRig, AGltfFileWithoutLightsGetsTheRigAndOneWithLightsKeepsItsOwn) {
  const Scene box = loadSceneFile(kModels + "box.gltf");
  ASSERT_EQ(box.lights.size(), 3u);
  EXPECT_EQ(box.lights[0].name, "rig-directional");
  EXPECT_GT(box.ambient.x, 0);
  bool said = false;
  for (const std::string& w : box.warnings) said = said || w.find("default rig") != std::string::npos;
  EXPECT_TRUE(said);

  const Scene lit = loadSceneFile(kModels + "punctual-lights.gltf");
  ASSERT_FALSE(lit.lights.empty());
  for (const Light& light : lit.lights) EXPECT_EQ(light.name.rfind("rig-", 0), std::string::npos) << light.name;
  EXPECT_EQ(lit.ambient, Vec3(0));
}

TEST(DefaultRig, AnImportMayAskForIt) {
  const std::string text = R"({"lightcts": 1, "image": {"width": 8, "height": 8},
    "camera": {"position": [0, 0, 6], "target": [0, 0, 0], "up": [0, 1, 0], "projection": "perspective"},
    "imports": [{"gltf": ")" + kModels + R"(punctual-lights.gltf", "lights": "default-rig"}],
    "objects": [], "lights": []})";
  const Scene scene = loadSceneText(text, "rigged.json");
  ASSERT_EQ(scene.lights.size(), 3u);  // the file's own lights replaced by the rig
  EXPECT_EQ(scene.lights[2].name, "rig-spot");
  EXPECT_GT(scene.ambient.x, 0);
  EXPECT_THROW(loadSceneText(text.substr(0, text.find("default-rig")) + "sunlight" +
                                 text.substr(text.find("default-rig") + 11),
                             "bad.json"),
               SceneLoadError);
}

TEST(DefaultRig, TheScenePrintedForAGltfFileLoadsAsTheSameScene) {
  const std::string file = kModels + "sphere.gltf";
  const Scene bare = loadSceneFile(file);
  const std::string printed = bareGltfSceneJson(bare, file).dump(2);
  // A name of its own: ctest runs each test in its own process, beside other checkouts' tests.
  const std::filesystem::path saved =
      std::filesystem::path(::testing::TempDir()) / ("lightcts-rig-scene-" + std::to_string(::getpid()) + ".json");
  std::ofstream(saved) << printed;
  const Scene again = loadSceneFile(saved.string());
  std::filesystem::remove(saved);
  ASSERT_EQ(again.lights.size(), bare.lights.size());
  for (std::size_t i = 0; i < bare.lights.size(); ++i) {
    EXPECT_EQ(again.lights[i].name, bare.lights[i].name);
    EXPECT_EQ(again.lights[i].type, bare.lights[i].type);
    EXPECT_NEAR(glm::length(again.lights[i].position - bare.lights[i].position), 0, 1e-12);
    EXPECT_NEAR(again.lights[i].range, bare.lights[i].range, 1e-12);
    EXPECT_NEAR(again.lights[i].intensity, bare.lights[i].intensity, 1e-12);
    if (bare.lights[i].type != LightType::Point)  // a point light's direction is no part of it
      EXPECT_NEAR(glm::length(again.lights[i].direction - bare.lights[i].direction), 0, 1e-12);
    EXPECT_NEAR(glm::length(again.lights[i].color - bare.lights[i].color), 0, 1e-12);
    EXPECT_NEAR(again.lights[i].spotAngleDeg, bare.lights[i].spotAngleDeg, 1e-12);
    ASSERT_EQ(again.lights[i].innerSpotAngleDeg.has_value(), bare.lights[i].innerSpotAngleDeg.has_value());
    EXPECT_NEAR(again.lights[i].innerSpotAngleDeg.value_or(0), bare.lights[i].innerSpotAngleDeg.value_or(0), 1e-12);
    EXPECT_EQ(again.lights[i].mode, bare.lights[i].mode);
  }
  EXPECT_EQ(again.objects.size(), bare.objects.size());
  EXPECT_EQ(again.ambient, bare.ambient);
  EXPECT_NEAR(glm::length(again.camera.position - bare.camera.position), 0, 1e-12);
}

}  // namespace
}  // namespace scene_input
