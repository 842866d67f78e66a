// Tests of the scene loader (SPEC 2) and of the JSON positions it reports.
// Every expected line and column is counted by hand in the literal next to it.
#include "lighting/scene_words.h"
#include "scene_input/json_locations.h"
#include "scene_input/scene_loader.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <ostream>
#include <string>
#include <string_view>

namespace glm {
// Readable failure messages for Vec3 comparisons.
void PrintTo(const dvec3& v, std::ostream* os) { *os << "[" << v.x << ", " << v.y << ", " << v.z << "]"; }
}  // namespace glm

namespace scene_input {
namespace {

using namespace lighting;

// Loads text that must be rejected and returns the error.
SceneError loadError(std::string_view text) {
  try {
    loadSceneText(text, "scene.json");
  } catch (const SceneLoadError& error) {
    return error.error();
  }
  ADD_FAILURE() << "the scene loaded, but an error was expected:\n" << text;
  return {};
}

void expectError(std::string_view text, std::string_view jsonPath, int line, int column,
                 std::string_view messagePart) {
  const SceneError error = loadError(text);
  EXPECT_EQ(error.file, "scene.json");
  EXPECT_EQ(error.jsonPath, jsonPath);
  EXPECT_EQ(error.line, line);
  EXPECT_EQ(error.column, column);
  EXPECT_NE(error.message.find(messagePart), std::string::npos)
      << "message: " << error.message << "\nexpected it to contain: " << messagePart;
}

// A valid scene around the objects and lights under test, laid out so that
// columns are easy to count:
//   line 2 is ` "objects": ` (12 characters), so the objects array starts at column 13;
//   line 3 is ` "lights": ` (11 characters), so the lights array starts at column 12.
std::string sceneWith(std::string_view objects, std::string_view lights) {
  return std::string("{\"lightcts\": 1, \"image\": {}, \"camera\": {},\n \"objects\": ") + std::string(objects) +
         ",\n \"lights\": " + std::string(lights) + "}";
}

std::string sceneWithLights(std::string_view lights) { return sceneWith("[]", lights); }
std::string sceneWithObjects(std::string_view objects) { return sceneWith(objects, "[]"); }

// SPEC 2's example, verbatim.
constexpr std::string_view kSpecExample = R"json({
  "lightcts": 1,
  "name": "spot-inner-outer",
  "description": "one spot light, inner 30, outer 60, on a plane",
  "image":  {"width": 128, "height": 128},
  "camera": {"position": [0, 10, 0], "target": [0, 0, 0], "up": [0, 0, -1],
             "projection": "orthographic", "height": 10, "near": 0.1, "far": 100},
  "pipeline": {"profile": "srp", "path": "forward", "lights_per_object": false,
               "deferred_buffer": "hdr32"},
  "ambient": [0, 0, 0],
  "objects": [
    {"name": "floor",
     "mesh": {"type": "plane", "size": [10, 10], "subdivisions": 1},
     "transform": {"translate": [0, 0, 0], "rotate_deg": [0, 0, 0], "scale": 1},
     "material": {"albedo": [1, 1, 1]},
     "static": false, "lightmap_resolution": 0}
  ],
  "lights": [
    {"name": "s0", "type": "spot", "position": [0, 2, 0], "direction": [0, -1, 0],
     "range": 6, "spot_angle_deg": 60, "inner_spot_angle_deg": 30,
     "color": [1, 1, 1], "intensity": 2, "mode": "realtime",
     "shadows": false, "shadow_strength": 1, "bake_falloff": "inverse_squared"}
  ],
  "frames": {"count": 1, "camera_path": []},
  "expect": {"tolerance_scale": 1, "max_failing_pixels": 0, "expect_fail": false}
}
)json";

// ---------------------------------------------------------------------------
// Scenes that load

TEST(SceneLoader, MinimalSceneGetsEveryDefaultOfTheSpecExample) {
  const Scene scene = loadSceneText(
      R"({"lightcts": 1, "image": {}, "camera": {}, "objects": [{}], "lights": [{}]})",
      "suite/scenes/attenuation/minimal.json");

  EXPECT_EQ(scene.sourcePath, "suite/scenes/attenuation/minimal.json");
  EXPECT_EQ(scene.name, "minimal");  // the file's stem
  EXPECT_EQ(scene.description, "");
  EXPECT_EQ(scene.image.width, 128);
  EXPECT_EQ(scene.image.height, 128);

  EXPECT_EQ(scene.camera.position, Vec3(0, 10, 0));
  EXPECT_EQ(scene.camera.target, Vec3(0, 0, 0));
  EXPECT_EQ(scene.camera.up, Vec3(0, 0, -1));
  EXPECT_EQ(scene.camera.projection, Projection::Orthographic);
  EXPECT_EQ(scene.camera.orthoHeight, 10);
  EXPECT_EQ(scene.camera.fovYDeg, 60);
  EXPECT_EQ(scene.camera.nearPlane, 0.1);
  EXPECT_EQ(scene.camera.farPlane, 100);

  EXPECT_EQ(scene.pipeline.profile, Profile::Srp);
  EXPECT_EQ(scene.pipeline.path, RenderPath::Forward);
  EXPECT_FALSE(scene.pipeline.lightsPerObject);
  EXPECT_EQ(scene.pipeline.deferredBuffer, DeferredBuffer::Hdr32);
  EXPECT_EQ(scene.ambient, Vec3(0, 0, 0));

  ASSERT_EQ(scene.objects.size(), 1u);
  const Object& object = scene.objects[0];
  EXPECT_EQ(object.name, "object0");
  EXPECT_EQ(object.mesh.type, MeshType::Plane);
  EXPECT_EQ(object.mesh.planeSizeX, 10);
  EXPECT_EQ(object.mesh.planeSizeZ, 10);
  EXPECT_EQ(object.mesh.subdivisions, 1);
  EXPECT_EQ(object.transform.translate, Vec3(0, 0, 0));
  EXPECT_EQ(object.transform.rotateDeg, Vec3(0, 0, 0));
  EXPECT_EQ(object.transform.scale, 1);
  EXPECT_EQ(object.albedo, Vec3(1, 1, 1));
  EXPECT_FALSE(object.isStatic);
  EXPECT_EQ(object.lightmapResolution, 0);

  ASSERT_EQ(scene.lights.size(), 1u);
  const Light& light = scene.lights[0];
  EXPECT_EQ(light.name, "light0");
  EXPECT_EQ(light.type, LightType::Spot);
  EXPECT_EQ(light.position, Vec3(0, 2, 0));
  EXPECT_EQ(light.direction, Vec3(0, -1, 0));
  EXPECT_EQ(light.range, 6);
  EXPECT_EQ(light.spotAngleDeg, 60);
  EXPECT_FALSE(light.innerSpotAngleDeg.has_value());  // optional: absent means the rule of SPEC 3.4
  EXPECT_EQ(light.color, Vec3(1, 1, 1));
  EXPECT_EQ(light.intensity, 2);
  EXPECT_EQ(light.mode, LightMode::Realtime);
  EXPECT_FALSE(light.shadows);
  EXPECT_EQ(light.shadowStrength, 1);
  EXPECT_EQ(light.bakeFalloff, BakeFalloff::InverseSquared);

  EXPECT_EQ(scene.frames.count, 1);
  EXPECT_TRUE(scene.frames.cameraPath.empty());
  EXPECT_EQ(scene.expect.toleranceScale, 1);
  EXPECT_EQ(scene.expect.maxFailingPixels, 0);
  EXPECT_FALSE(scene.expect.expectFail);
  EXPECT_EQ(scene.expect.against, CompareAgainst::Reference);
}

TEST(SceneLoader, SpecExampleLoadsWithTheValuesWritten) {
  const Scene scene = loadSceneText(kSpecExample, "spec-example.json");

  EXPECT_EQ(scene.name, "spot-inner-outer");
  EXPECT_EQ(scene.description, "one spot light, inner 30, outer 60, on a plane");
  EXPECT_EQ(scene.image.width, 128);
  EXPECT_EQ(scene.image.height, 128);
  EXPECT_EQ(scene.camera.position, Vec3(0, 10, 0));
  EXPECT_EQ(scene.camera.up, Vec3(0, 0, -1));
  EXPECT_EQ(scene.camera.projection, Projection::Orthographic);
  EXPECT_EQ(scene.camera.orthoHeight, 10);
  EXPECT_EQ(scene.camera.nearPlane, 0.1);
  EXPECT_EQ(scene.camera.farPlane, 100);
  ASSERT_EQ(scene.objects.size(), 1u);
  EXPECT_EQ(scene.objects[0].name, "floor");
  EXPECT_EQ(scene.objects[0].mesh.planeSizeX, 10);
  ASSERT_EQ(scene.lights.size(), 1u);
  const Light& light = scene.lights[0];
  EXPECT_EQ(light.name, "s0");
  EXPECT_EQ(light.type, LightType::Spot);
  EXPECT_EQ(light.range, 6);
  EXPECT_EQ(light.spotAngleDeg, 60);
  ASSERT_TRUE(light.innerSpotAngleDeg.has_value());
  EXPECT_EQ(*light.innerSpotAngleDeg, 30);
  EXPECT_EQ(light.intensity, 2);
  EXPECT_EQ(light.finalColor(), Vec3(2, 2, 2));
  EXPECT_EQ(scene.frames.count, 1);
  EXPECT_EQ(scene.expect.maxFailingPixels, 0);
}

TEST(SceneLoader, EveryKeyWithAValueOtherThanItsDefault) {
  const Scene scene = loadSceneText(R"({
    "lightcts": 1, "name": "custom", "description": "d",
    "image": {"width": 64, "height": 32},
    "camera": {"position": [1, 2, 3], "target": [1, 2, 0], "up": [0, 1, 0],
               "projection": "perspective", "fov_y_deg": 45, "near": 0.5, "far": 50},
    "pipeline": {"profile": "legacy", "path": "deferred", "lights_per_object": true,
                 "deferred_buffer": "ldr8"},
    "ambient": [0.1, 0.2, 0.3],
    "objects": [
      {"name": "ball", "mesh": {"type": "sphere", "radius": 2, "segments": 8, "rings": 4},
       "transform": {"translate": [1, 2, 3], "rotate_deg": [10, 20, 30], "scale": 0.5},
       "material": {"albedo": [0.5, 0.25, 0]}},
      {"mesh": {"type": "box", "size": [1, 2, 3]}},
      {"mesh": {"type": "plane", "size": [4, 6], "subdivisions": 3},
       "static": true, "lightmap_resolution": 64}
    ],
    "lights": [
      {"type": "directional", "direction": [0, -2, 0], "color": [1, 0.5, 0], "intensity": 0,
       "mode": "mixed", "shadows": true, "shadow_strength": 0.5, "bake_falloff": "legacy"},
      {"type": "point", "position": [5, 6, 7], "range": 3, "mode": "baked",
       "bake_falloff": "inverse_squared_no_range"},
      {"spot_angle_deg": 180, "inner_spot_angle_deg": 180}
    ],
    "frames": {"count": 3, "camera_path": [{"position": [0, 1, 5], "target": [0, 0, 0]},
                                           {"position": [5, 1, 0], "target": [1, 0, 0]}]},
    "expect": {"tolerance_scale": 2.5, "max_failing_pixels": 7, "expect_fail": true, "against": "realtime"}
  })",
                                    "ignored-stem.json");

  EXPECT_EQ(scene.name, "custom");
  EXPECT_EQ(scene.description, "d");
  EXPECT_EQ(scene.image.width, 64);
  EXPECT_EQ(scene.image.height, 32);
  EXPECT_EQ(scene.camera.position, Vec3(1, 2, 3));
  EXPECT_EQ(scene.camera.target, Vec3(1, 2, 0));
  EXPECT_EQ(scene.camera.up, Vec3(0, 1, 0));
  EXPECT_EQ(scene.camera.projection, Projection::Perspective);
  EXPECT_EQ(scene.camera.fovYDeg, 45);
  EXPECT_EQ(scene.camera.nearPlane, 0.5);
  EXPECT_EQ(scene.camera.farPlane, 50);
  EXPECT_EQ(scene.pipeline.profile, Profile::Legacy);
  EXPECT_EQ(scene.pipeline.path, RenderPath::Deferred);
  EXPECT_TRUE(scene.pipeline.lightsPerObject);
  EXPECT_EQ(scene.pipeline.deferredBuffer, DeferredBuffer::Ldr8);
  EXPECT_EQ(scene.ambient, Vec3(0.1, 0.2, 0.3));

  ASSERT_EQ(scene.objects.size(), 3u);
  const Object& ball = scene.objects[0];
  EXPECT_EQ(ball.name, "ball");
  EXPECT_EQ(ball.mesh.type, MeshType::Sphere);
  EXPECT_EQ(ball.mesh.sphereRadius, 2);
  EXPECT_EQ(ball.mesh.sphereSegments, 8);
  EXPECT_EQ(ball.mesh.sphereRings, 4);
  EXPECT_EQ(ball.transform.translate, Vec3(1, 2, 3));
  EXPECT_EQ(ball.transform.rotateDeg, Vec3(10, 20, 30));
  EXPECT_EQ(ball.transform.scale, 0.5);
  EXPECT_EQ(ball.albedo, Vec3(0.5, 0.25, 0));
  EXPECT_EQ(scene.objects[1].name, "object1");
  EXPECT_EQ(scene.objects[1].mesh.type, MeshType::Box);
  EXPECT_EQ(scene.objects[1].mesh.boxSize, Vec3(1, 2, 3));
  const Object& floor = scene.objects[2];
  EXPECT_EQ(floor.mesh.planeSizeX, 4);
  EXPECT_EQ(floor.mesh.planeSizeZ, 6);
  EXPECT_EQ(floor.mesh.subdivisions, 3);
  EXPECT_TRUE(floor.hasLightmap());
  EXPECT_EQ(floor.lightmapResolution, 64);

  ASSERT_EQ(scene.lights.size(), 3u);
  const Light& sun = scene.lights[0];
  EXPECT_EQ(sun.name, "light0");
  EXPECT_EQ(sun.type, LightType::Directional);
  EXPECT_EQ(sun.direction, Vec3(0, -1, 0));
  EXPECT_EQ(sun.color, Vec3(1, 0.5, 0));
  EXPECT_EQ(sun.intensity, 0);
  EXPECT_EQ(sun.mode, LightMode::Mixed);
  EXPECT_TRUE(sun.shadows);
  EXPECT_EQ(sun.shadowStrength, 0.5);
  EXPECT_EQ(sun.bakeFalloff, BakeFalloff::Legacy);
  const Light& point = scene.lights[1];
  EXPECT_EQ(point.type, LightType::Point);
  EXPECT_EQ(point.position, Vec3(5, 6, 7));
  EXPECT_EQ(point.range, 3);
  EXPECT_EQ(point.mode, LightMode::Baked);
  EXPECT_EQ(point.bakeFalloff, BakeFalloff::InverseSquaredNoRange);
  EXPECT_EQ(scene.lights[2].spotAngleDeg, 180);  // the closed end of (0, 180]
  EXPECT_EQ(scene.lights[2].innerSpotAngleDeg, 180.0);

  EXPECT_EQ(scene.frames.count, 3);
  ASSERT_EQ(scene.frames.cameraPath.size(), 2u);
  EXPECT_EQ(scene.frames.cameraPath[1].position, Vec3(5, 1, 0));
  EXPECT_EQ(scene.frames.cameraPath[1].target, Vec3(1, 0, 0));
  EXPECT_EQ(scene.expect.toleranceScale, 2.5);
  EXPECT_EQ(scene.expect.maxFailingPixels, 7);
  EXPECT_TRUE(scene.expect.expectFail);
  EXPECT_EQ(scene.expect.against, CompareAgainst::Realtime);
}

// `expect.against` is an extension of SPEC 2 (docs/scene-format.md).
TEST(SceneLoader, ExpectAgainstReferenceOrRealtime) {
  const std::string head = R"({"lightcts": 1, "image": {}, "camera": {}, "objects": [], "lights": [], "expect": )";
  EXPECT_EQ(loadSceneText(head + R"({"against": "reference"}})", "scene.json").expect.against,
            CompareAgainst::Reference);
  EXPECT_EQ(loadSceneText(head + R"({"against": "realtime"}})", "scene.json").expect.against,
            CompareAgainst::Realtime);
  EXPECT_EQ(loadSceneText(head + "{}}", "scene.json").expect.against, CompareAgainst::Reference);
}

TEST(SceneLoaderError, ExpectAgainstOtherValuesAreRejectedWithTheirPath) {
  // Line 2 is ` "expect": {"against": ` (23 characters): the value starts at column 24.
  const std::string head = "{\"lightcts\": 1, \"image\": {}, \"camera\": {}, \"objects\": [], \"lights\": [],\n"
                           " \"expect\": {\"against\": ";
  expectError(head + "\"baked\"}}", "/expect/against", 2, 24,
              "expected one of: reference, realtime; got 'baked'");
  expectError(head + "\"Realtime\"}}", "/expect/against", 2, 24,
              "expected one of: reference, realtime; got 'Realtime'");
  expectError(head + "1}}", "/expect/against", 2, 24, "expected one of: reference, realtime; got a number");
  // An unknown key next to it still lists the allowed ones, `against` included.
  expectError(head + "\"realtime\", \"agianst\": 1}}", "/expect/agianst", 2, 36,
              "expected one of: tolerance_scale, max_failing_pixels, expect_fail, against");
}

TEST(SceneLoader, DirectionIsNormalised) {
  // |(3, 0, -4)| = 5.
  const Scene scene = loadSceneText(sceneWithLights(R"([{"direction": [3, 0, -4]}])"), "scene.json");
  EXPECT_DOUBLE_EQ(scene.lights[0].direction.x, 0.6);
  EXPECT_DOUBLE_EQ(scene.lights[0].direction.y, 0.0);
  EXPECT_DOUBLE_EQ(scene.lights[0].direction.z, -0.8);
}

TEST(SceneLoader, TinyDirectionIsNormalisedWithoutUnderflow) {
  // Squaring 1e-200 underflows to 0; the loader must still find the unit vector.
  const Scene scene = loadSceneText(sceneWithLights(R"([{"direction": [0, 1e-200, 0]}])"), "scene.json");
  EXPECT_EQ(scene.lights[0].direction, Vec3(0, 1, 0));
}

TEST(SceneLoader, AbsentInnerAngleStaysAbsentAndZeroIsAllowed) {
  const Scene scene =
      loadSceneText(sceneWithLights(R"([{"spot_angle_deg": 40}, {"inner_spot_angle_deg": 0}])"), "scene.json");
  EXPECT_FALSE(scene.lights[0].innerSpotAngleDeg.has_value());
  ASSERT_TRUE(scene.lights[1].innerSpotAngleDeg.has_value());
  EXPECT_EQ(*scene.lights[1].innerSpotAngleDeg, 0);
}

TEST(SceneLoader, ThreeEqualScaleValuesAreAUniformScale) {
  const Scene scene = loadSceneText(sceneWithObjects(R"([{"transform": {"scale": [2, 2, 2]}}])"), "scene.json");
  EXPECT_EQ(scene.objects[0].transform.scale, 2);
}

TEST(SceneLoader, IntegralNumberWrittenWithAFractionIsAnInteger) {
  const Scene scene = loadSceneText(
      R"({"lightcts": 1.0, "image": {"width": 64.0}, "camera": {}, "objects": [], "lights": []})", "scene.json");
  EXPECT_EQ(scene.image.width, 64);
}

TEST(SceneLoader, LightKeysOfOtherTypesAreAcceptedAndKept) {
  const Scene scene =
      loadSceneText(sceneWithLights(R"([{"type": "directional", "range": 3, "spot_angle_deg": 20}])"), "scene.json");
  EXPECT_EQ(scene.lights[0].range, 3);
  EXPECT_EQ(scene.lights[0].spotAngleDeg, 20);
}

TEST(SceneLoader, FileLoadsWithItsStemAsName) {
  const std::filesystem::path path =
      std::filesystem::path(testing::TempDir()) / "lightcts-scene-loader-test-stem.json";
  {
    std::ofstream out(path);
    out << R"({"lightcts": 1, "image": {}, "camera": {}, "objects": [], "lights": []})";
  }
  const Scene scene = loadSceneFile(path.string());
  std::filesystem::remove(path);
  EXPECT_EQ(scene.name, "lightcts-scene-loader-test-stem");
  EXPECT_EQ(scene.sourcePath, path.string());
}

// ---------------------------------------------------------------------------
// Scenes that are rejected: one test per class of bad input.

TEST(SceneLoaderError, UnknownKeyPointsAtTheKeyAndListsTheAllowedOnes) {
  // Line 3: ` "lights": [{"rnage": 6}]`: '[' at 12, '{' at 13, the key at 14.
  expectError(sceneWithLights(R"([{"rnage": 6}])"), "/lights/0/rnage", 3, 14,
              "unknown key 'rnage'; expected one of: name, type, position, direction, range, spot_angle_deg");
}

TEST(SceneLoaderError, UnknownTopLevelKeyWithPointerEscapes) {
  // RFC 6901: '/' is written "~1" and '~' is written "~0". Column 2 is the key's quote.
  expectError(R"({"a/b~c": 1, "lightcts": 1, "image": {}, "camera": {}, "objects": [], "lights": []})", "/a~1b~0c",
              1, 2, "unknown key 'a/b~c'");
}

TEST(SceneLoaderError, WrongType) {
  // Line 3: ` "lights": [{"range": "6"}]`: the key spans 14-20, ':' 21, ' ' 22, the value 23.
  expectError(sceneWithLights(R"([{"range": "6"}])"), "/lights/0/range", 3, 23, "expected a number, got a string");
  expectError(sceneWithLights(R"([{"shadows": 1}])"), "/lights/0/shadows", 3, 25, "expected true or false, got a number");
}

TEST(SceneLoaderError, NumberTooLargeForADouble) {
  expectError(sceneWithLights(R"([{"range": 1e999}])"), "/lights/0/range", 3, 23,
              "non-finite numbers (NaN, Infinity) are not allowed in a scene; 1e999 is too large");
}

TEST(SceneLoaderError, NaNAndInfinityLiteralsAreParseErrorsWithAClearMessage) {
  // The parser has no JSON path yet; the position is where the literal starts.
  expectError(sceneWithLights(R"([{"range": NaN}])"), "", 3, 23,
              "non-finite numbers (NaN, Infinity) are not allowed in a scene; found 'NaN'");
  expectError(sceneWithLights(R"([{"range": -Infinity}])"), "", 3, 23, "found '-Infinity'");
}

TEST(SceneLoaderError, InvalidJsonGivesTheParserPosition) {
  // The trailing comma makes the '}' on line 3, column 1 unexpected.
  expectError("{\"lightcts\": 1,\n \"image\": {},\n}", "", 3, 1, "invalid JSON: syntax error");
}

TEST(SceneLoaderError, OutOfRangeValues) {
  // Line 3 as above: after ` "lights": [{` the first key starts at 14.
  expectError(sceneWithLights(R"([{"range": -1}])"), "/lights/0/range", 3, 23, "expected a number > 0, got -1");
  // `[{}, {"range": 0}]`: second light's '{' at 17, key 18-24, value at 27.
  expectError(sceneWithLights(R"([{}, {"range": 0}])"), "/lights/1/range", 3, 27, "expected a number > 0, got 0");
  // "spot_angle_deg" with quotes is 16 characters (14-29), ':' 30, ' ' 31, value 32.
  expectError(sceneWithLights(R"([{"spot_angle_deg": 0}])"), "/lights/0/spot_angle_deg", 3, 32,
              "expected a number in (0, 180], got 0");
  expectError(sceneWithLights(R"([{"spot_angle_deg": 181}])"), "/lights/0/spot_angle_deg", 3, 32,
              "expected a number in (0, 180], got 181");
  // `40, ` ends at 35; "inner_spot_angle_deg" is 22 characters (36-57), ':' 58, ' ' 59, value 60.
  expectError(sceneWithLights(R"([{"spot_angle_deg": 40, "inner_spot_angle_deg": 50}])"),
              "/lights/0/inner_spot_angle_deg", 3, 60, "expected a number in [0, 40], got 50");
  // "shadow_strength" is 17 characters (14-30), ':' 31, ' ' 32, value 33.
  expectError(sceneWithLights(R"([{"shadow_strength": 1.5}])"), "/lights/0/shadow_strength", 3, 33,
              "expected a number in [0, 1], got 1.5");
  // Line 2: ` "objects": [{"material": {"albedo": [1, 1.5, 0]}}]`: '{' 14, "material" 15-24,
  // '{' 27, "albedo" 28-35, '[' 38, '1' 39, ',' 40, ' ' 41, 1.5 at 42.
  expectError(sceneWithObjects(R"([{"material": {"albedo": [1, 1.5, 0]}}])"), "/objects/0/material/albedo/1", 2,
              42, "expected a number in [0, 1], got 1.5");
  expectError(sceneWithLights(R"([{"mode": "sometimes"}])"), "/lights/0/mode", 3, 22,
              "expected one of: realtime, mixed, baked; got 'sometimes'");
}

TEST(SceneLoaderError, NonIntegerWhereAnIntegerIsRequired) {
  // Line 2: '{' 23 opens the mesh, "subdivisions" is 14 characters (24-37), ':' 38, ' ' 39, value 40.
  expectError(sceneWithObjects(R"([{"mesh": {"subdivisions": 2.5}}])"), "/objects/0/mesh/subdivisions", 2, 40,
              "expected an integer in [1, 4096], got 2.5");
  // `{"lightcts": 1, "image": {"width": 0}`: '{' of image at 26, "width" 27-33, value 36.
  expectError(R"({"lightcts": 1, "image": {"width": 0}, "camera": {}, "objects": [], "lights": []})", "/image/width", 1,
              36, "expected an integer in [1, 8192], got 0");
}

TEST(SceneLoader, FadeLastLightsDefaultsToZeroAndReadsItsValue) {
  EXPECT_EQ(loadSceneText(sceneWithLights("[]"), "scene.json").pipeline.fadeLastLights, 0);
  auto fadeOf = [](std::string_view pipeline) {
    return loadSceneText(std::string(R"({"lightcts": 1, "pipeline": )") + std::string(pipeline) +
                             R"(, "image": {}, "camera": {}, "objects": [], "lights": []})",
                         "scene.json")
        .pipeline.fadeLastLights;
  };
  EXPECT_EQ(fadeOf(R"({"fade_last_lights": 8})"), 8);
  EXPECT_EQ(fadeOf(R"({"fade_last_lights": 64})"), 64);
  EXPECT_EQ(fadeOf(R"({"fade_last_lights": 0})"), 0);
  EXPECT_EQ(fadeOf(R"({"profile": "legacy", "fade_last_lights": 16})"), 16);
  EXPECT_EQ(fadeOf(R"({"fade_last_lights": 16, "profile": "legacy"})"), 16);
}

TEST(SceneLoaderError, FadeLastLightsOutOfRangeForTheProfile) {
  // '{' 1, "lightcts" 2-11, '1' 14, ',' 15, "pipeline" 17-26, ':' 27, ' ' 28, '{' 29,
  // "fade_last_lights" (18 characters) 30-47, ':' 48, ' ' 49, the value at 50.
  const std::string tail = R"(, "image": {}, "camera": {}, "objects": [], "lights": []})";
  expectError(R"({"lightcts": 1, "pipeline": {"fade_last_lights": 65})" + tail, "/pipeline/fade_last_lights", 1, 50,
              "expected an integer in [0, 64], got 65");
  expectError(R"({"lightcts": 1, "pipeline": {"fade_last_lights": -1})" + tail, "/pipeline/fade_last_lights", 1, 50,
              "expected an integer in [0, 64], got -1");
  expectError(R"({"lightcts": 1, "pipeline": {"fade_last_lights": 2.5})" + tail, "/pipeline/fade_last_lights", 1, 50,
              "expected an integer in [0, 64], got 2.5");
  expectError(R"({"lightcts": 1, "pipeline": {"fade_last_lights": true})" + tail, "/pipeline/fade_last_lights", 1,
              50, "expected an integer in [0, 64], got a boolean");
  // Legacy keeps 16, whichever key comes first. After the profile: "profile" 30-38,
  // "legacy" 41-48, ',' 49, "fade_last_lights" 51-68, ':' 69, ' ' 70, the value at 71.
  expectError(R"({"lightcts": 1, "pipeline": {"fade_last_lights": 17, "profile": "legacy"})" + tail,
              "/pipeline/fade_last_lights", 1, 50,
              "expected an integer in [0, 16] (the legacy profile keeps 16 lights), got 17");
  expectError(R"({"lightcts": 1, "pipeline": {"profile": "legacy", "fade_last_lights": 17})" + tail,
              "/pipeline/fade_last_lights", 1, 71,
              "expected an integer in [0, 16] (the legacy profile keeps 16 lights), got 17");
}

TEST(SceneLoaderError, ZeroDirection) {
  // "direction" is 11 characters (14-24), ':' 25, ' ' 26, '[' 27.
  expectError(sceneWithLights(R"([{"direction": [0, 0, 0]}])"), "/lights/0/direction", 3, 27,
              "direction must not be the zero vector");
}

TEST(SceneLoaderError, VectorOfTheWrongLength) {
  expectError(sceneWithLights(R"([{"direction": [0, -1]}])"), "/lights/0/direction", 3, 27,
              "expected an array of 3 numbers, got an array of 2 values");
}

TEST(SceneLoaderError, NonUniformScale) {
  // Line 2: "transform" 15-25, ':' 26, ' ' 27, '{' 28, "scale" 29-35, ':' 36, ' ' 37, '[' 38.
  expectError(sceneWithObjects(R"([{"transform": {"scale": [1, 2, 1]}}])"), "/objects/0/transform/scale", 2, 38,
              "non-uniform scale is not part of the model (SPEC 1)");
}

TEST(SceneLoaderError, KeyOfAnotherMeshType) {
  // Line 2: "mesh" 15-20, ':' 21, ' ' 22, '{' 23, the key "radius" at 24.
  expectError(sceneWithObjects(R"([{"mesh": {"radius": 2}}])"), "/objects/0/mesh/radius", 2, 24,
              "key 'radius' does not apply to mesh type 'plane'");
}

TEST(SceneLoaderError, LightmapOnASphere) {
  // Line 2: '{' 23, "type" 24-29, "sphere" 32-39, '}' 40, ',' 41, "static" 43-50, true 53-56,
  // ',' 57, "lightmap_resolution" 59-79, ':' 80, ' ' 81, value 82.
  expectError(sceneWithObjects(R"([{"mesh": {"type": "sphere"}, "static": true, "lightmap_resolution": 32}])"),
              "/objects/0/lightmap_resolution", 2, 82, "lightmaps are only supported on planes (SPEC 2)");
}

TEST(SceneLoaderError, AreaLight) {
  // "type" 14-19, ':' 20, ' ' 21, the value 22.
  expectError(sceneWithLights(R"([{"type": "area"}])"), "/lights/0/type", 3, 22,
              "area lights are not part of this model yet (baked-only area lights, SPEC 2)");
}

TEST(SceneLoaderError, WrongFormatVersion) {
  // '{' 1, "lightcts" 2-11, ':' 12, ' ' 13, the value 14.
  expectError(R"({"lightcts": 2, "image": {}, "camera": {}, "objects": [], "lights": []})", "/lightcts", 1, 14,
              "unsupported format version 2; this loader reads version 1");
  expectError(R"({"lightcts": "1", "image": {}, "camera": {}, "objects": [], "lights": []})", "/lightcts", 1, 14,
              "expected the format version 1, got a string");
}

TEST(SceneLoaderError, MissingRequiredKeyPointsAtTheObjectThatLacksIt) {
  expectError("{\"lightcts\": 1, \"image\": {},\n \"objects\": [], \"lights\": []}", "/camera", 1, 1,
              "missing required key 'camera'");
  // A keyframe lacks "target". Line 2: '[' 40, the first keyframe 41-84 ("position" 42-51,
  // [1, 0, 0] 54-62, "target" 65-72, [0, 0, 0] 75-83, '}' 84), ',' 85, ' ' 86, the second '{' at 87.
  expectError("{\"lightcts\": 1, \"image\": {}, \"camera\": {}, \"objects\": [], \"lights\": [],\n"
              " \"frames\": {\"count\": 2, \"camera_path\": [{\"position\": [1, 0, 0], \"target\": [0, 0, 0]}, "
              "{\"position\": [1, 0, 0]}]}}",
              "/frames/camera_path/1/target", 2, 87, "missing required key 'target'");
}

TEST(SceneLoaderError, CameraPathWithOneKeyframe) {
  // Line 2: ` "frames": {"count": 2, "camera_path": [`: "frames" 2-9, '{' 12, "count" 13-19,
  // '2' 22, "camera_path" 25-37, ':' 38, ' ' 39, '[' 40.
  expectError(R"({"lightcts": 1, "image": {}, "camera": {}, "objects": [], "lights": [],
 "frames": {"count": 2, "camera_path": [{"position": [0, 10, 0], "target": [0, 0, 0]}]}})",
              "/frames/camera_path", 2, 40, "at least 2, got 1");
  // SPEC 2's t = f / (count - 1) needs two frames or more; '1' is at column 22 as above.
  expectError(R"({"lightcts": 1, "image": {}, "camera": {}, "objects": [], "lights": [],
 "frames": {"count": 1, "camera_path": [{"position": [0, 10, 0], "target": [0, 0, 0]},
                                        {"position": [0, 10, 1], "target": [0, 0, 0]}]}})",
              "/frames/count", 2, 22, "a camera path needs frames.count >= 2, got 1");
}

TEST(SceneLoaderError, CameraThatCannotLookAtItsTarget) {
  // Line 2: "camera" 2-9, '{' 12, "position" 13-22, '[' 25, ']' 34, "up" 37-40, '[' 43.
  expectError(R"({"lightcts": 1, "image": {}, "objects": [], "lights": [],
 "camera": {"position": [0, 10, 0], "up": [0, 1, 0]}})",
              "/camera/up", 2, 43, "is parallel to the view direction");
  // "target" 37-44, ':' 45, ' ' 46, '[' 47.
  expectError(R"({"lightcts": 1, "image": {}, "objects": [], "lights": [],
 "camera": {"position": [0, 10, 0], "target": [0, 10, 0]}})",
              "/camera/target", 2, 47, "target must differ from position");
  // "near" 13-18, ':' 19, ' ' 20, '5' 21, ',' 22, ' ' 23, "far" 24-28, ':' 29, ' ' 30, '1' 31.
  expectError(R"({"lightcts": 1, "image": {}, "objects": [], "lights": [],
 "camera": {"near": 5, "far": 1}})",
              "/camera/far", 2, 31, "expected far > near (5), got 1");
}

TEST(SceneLoaderError, PerspectiveKeyOnAnOrthographicCamera) {
  // Line 2: '{' 12, the key "fov_y_deg" at 13.
  expectError(R"({"lightcts": 1, "image": {}, "objects": [], "lights": [],
 "camera": {"fov_y_deg": 45}})",
              "/camera/fov_y_deg", 2, 13, "key 'fov_y_deg' does not apply to projection 'orthographic'");
}

TEST(SceneLoaderError, DuplicateKeyPointsAtTheSecondOne) {
  // `[{"range": 1, "range": 2}]`: the first key 14-20, '1' 23, ',' 24, the second key at 26.
  expectError(sceneWithLights(R"([{"range": 1, "range": 2}])"), "/lights/0/range", 3, 26, "duplicate key 'range'");
}

TEST(SceneLoaderError, UnreadableFile) {
  const std::string missing = std::string(LIGHTCTS_SOURCE_DIR) + "/suite/scenes/no-such-scene.json";
  try {
    loadSceneFile(missing);
    FAIL() << "a missing file loaded";
  } catch (const SceneLoadError& error) {
    EXPECT_EQ(error.error().file, missing);
    EXPECT_EQ(error.error().jsonPath, "");
    EXPECT_EQ(error.error().line, 0);
    EXPECT_NE(error.error().message.find("cannot open the scene file"), std::string::npos) << error.what();
    EXPECT_EQ(std::string(error.what()), missing + ": " + error.error().message);
  }
  try {
    loadSceneFile(LIGHTCTS_SOURCE_DIR);
    FAIL() << "a directory loaded";
  } catch (const SceneLoadError& error) {
    EXPECT_EQ(error.error().jsonPath, "");
    EXPECT_NE(error.error().message.find("it is a directory"), std::string::npos) << error.what();
  }
}

TEST(SceneLoaderError, FileErrorsNameTheFile) {
  const std::filesystem::path path = std::filesystem::path(testing::TempDir()) / "lightcts-scene-loader-bad.json";
  {
    std::ofstream out(path);
    out << "{\"lightcts\": 3}";
  }
  try {
    loadSceneFile(path.string());
    FAIL() << "a bad file loaded";
  } catch (const SceneLoadError& error) {
    EXPECT_EQ(std::string(error.what()), path.string() + ":1:14: /lightcts: " + error.error().message);
  }
  std::filesystem::remove(path);
}

TEST(SceneError, FormatLeavesOutWhatIsUnknown) {
  EXPECT_EQ((SceneError{"a.json", "/lights/3/range", 4, 7, "m"}.format()), "a.json:4:7: /lights/3/range: m");
  EXPECT_EQ((SceneError{"a.json", "/lights/3/range", 0, 0, "m"}.format()), "a.json: /lights/3/range: m");
  EXPECT_EQ((SceneError{"a.json", "", 2, 1, "m"}.format()), "a.json:2:1: m");
  EXPECT_EQ(std::string(SceneLoadError(SceneError{"a.json", "", 0, 0, "m"}).what()), "a.json: m");
}

// ---------------------------------------------------------------------------
// json_locations on its own

TEST(JsonLocations, PointerToValueAndToKey) {
  // Line 2: `  "b": [10, {"c~d": 1, "e/f": [true]}]`: "b" 3-5, '[' 8, "10" 9-10, '{' 13,
  // "c~d" 14-18, '1' 21, "e/f" 24-28, '[' 31, true 32.
  const std::string_view text = "{\"a\": 1,\n  \"b\": [10, {\"c~d\": 1, \"e/f\": [true]}]}";
  const auto at = [&](std::string_view pointer, JsonLocationTarget target = JsonLocationTarget::Value) {
    const auto position = locateJsonPointer(text, pointer, target);
    return position ? std::pair(position->line, position->column) : std::pair(0, 0);
  };
  EXPECT_EQ(at(""), std::pair(1, 1));
  EXPECT_EQ(at("/a"), std::pair(1, 7));
  EXPECT_EQ(at("/a", JsonLocationTarget::Key), std::pair(1, 2));
  EXPECT_EQ(at("/b/0"), std::pair(2, 9));
  EXPECT_EQ(at("/b/1/c~0d"), std::pair(2, 21));
  EXPECT_EQ(at("/b/1/c~0d", JsonLocationTarget::Key), std::pair(2, 14));
  EXPECT_EQ(at("/b/1/e~1f/0"), std::pair(2, 32));
  EXPECT_EQ(at("/b/0", JsonLocationTarget::Key), std::pair(2, 9));  // array elements have no key
  EXPECT_FALSE(locateJsonPointer(text, "/b/2").has_value());
  EXPECT_FALSE(locateJsonPointer(text, "/c~d").has_value());  // unescaped "~" matches nothing
}

TEST(JsonLocations, EscapedKeysAndMultiByteCharacters) {
  // The key "q\"\u00e9" decodes to q"é. Line 1: '{' 1, the key `"q\"\u00e9"` 2-12, ':' 13, ' ' 14,
  // the string "ü" 15-17 (ü is one character in two bytes), ',' 18, ' ' 19, "z" 20-22, ':' 23, ' ' 24,
  // 5 at 25 (26 if bytes were counted).
  const std::string_view text = "{\"q\\\"\\u00e9\": \"\xC3\xBC\", \"z\": 5}";
  const auto quoted = locateJsonPointer(text, "/q\"\xC3\xA9");
  ASSERT_TRUE(quoted.has_value());
  EXPECT_EQ(quoted->column, 15);
  const auto z = locateJsonPointer(text, "/z");
  ASSERT_TRUE(z.has_value());
  EXPECT_EQ(z->column, 25);
}

TEST(JsonLocations, CarriageReturnsDoNotCountAsColumnsBeforeTheValue) {
  // Windows line endings: line 2 is `"x": 1`, so 1 is at column 6.
  const auto position = locateJsonPointer("{\r\n\"x\": 1}", "/x");
  ASSERT_TRUE(position.has_value());
  EXPECT_EQ(position->line, 2);
  EXPECT_EQ(position->column, 6);
}

TEST(JsonLocations, PointerTokenEscaping) {
  EXPECT_EQ(escapeJsonPointerToken("a/b~c"), "a~1b~0c");
  EXPECT_EQ(unescapeJsonPointerToken("a~1b~0c"), "a/b~c");
  EXPECT_EQ(unescapeJsonPointerToken("~01"), "~1");  // "~0" first, then a plain '1'
}

TEST(JsonLocations, MalformedOrDeepTextStopsQuietly) {
  EXPECT_FALSE(locateJsonPointer("{\"a\": [1, ", "/a/1").has_value());
  const std::string deep = std::string(100000, '[') + std::string(100000, ']');
  EXPECT_TRUE(locateJsonPointer(deep, "/0/0").has_value());
  std::string tooDeep;  // the scanner gives up beyond a nesting depth no scene needs
  for (int i = 0; i < 1000; ++i) tooDeep += "/0";
  EXPECT_FALSE(locateJsonPointer(deep, tooDeep).has_value());
}

// deferredBufferName gives back the word the loader reads for each buffer.
TEST(SceneLoader, DeferredBufferNamesAreTheSceneFileWords) {
  const std::string head = R"({"lightcts": 1, "image": {}, "camera": {}, "objects": [], "lights": [], )";
  for (const DeferredBuffer buffer : {DeferredBuffer::Hdr32, DeferredBuffer::Hdr16, DeferredBuffer::Ldr8}) {
    const std::string name(deferredBufferName(buffer));
    const std::string text = head + R"("pipeline": {"path": "deferred", "deferred_buffer": ")" + name + "\"}}";
    EXPECT_EQ(loadSceneText(text, "scene.json").pipeline.deferredBuffer, buffer) << name;
  }
  EXPECT_EQ(deferredBufferName(DeferredBuffer::Hdr16), "hdr16");
}

TEST(SceneLoaderError, DeeplyNestedValueIsAnErrorNotACrash) {
  const std::string deep = std::string(100000, '[') + std::string(100000, ']');
  expectError(sceneWithLights(deep), "/lights/0", 3, 13, "expected an object, got an array");
}

// ---------------------------------------------------------------------------
// SPEC 2 materials: brdf, metallic, smoothness (SPEC 3.8)

TEST(SceneLoader, MaterialDefaultsToLambertAndSrpReadsMetallicAndSmoothness) {
  const Scene lambert = loadSceneText(sceneWithObjects(R"([{"material": {"albedo": [0.5, 0.5, 0.5]}}])"), "s.json");
  EXPECT_EQ(lambert.objects[0].brdf, Brdf::Lambert);
  const Scene srpDefaults = loadSceneText(sceneWithObjects(R"([{"material": {"brdf": "srp"}}])"), "s.json");
  EXPECT_EQ(srpDefaults.objects[0].brdf, Brdf::Srp);
  EXPECT_EQ(srpDefaults.objects[0].metallic, 0.0);
  EXPECT_EQ(srpDefaults.objects[0].smoothness, 0.5);
  const Scene srp = loadSceneText(
      sceneWithObjects(R"([{"material": {"brdf": "srp", "metallic": 1, "smoothness": 0.9}}])"), "s.json");
  EXPECT_EQ(srp.objects[0].metallic, 1.0);
  EXPECT_EQ(srp.objects[0].smoothness, 0.9);
}

TEST(SceneLoaderError, SrpMaterialKeysAndProfile) {
  // Line 2: ` "objects": [{"material": {"metallic": 0.5}}]`: '{' 27, "metallic" at 28.
  expectError(sceneWithObjects(R"([{"material": {"metallic": 0.5}}])"), "/objects/0/material/metallic", 2, 28,
              "key 'metallic' does not apply to brdf 'lambert'");
  expectError(sceneWithObjects(R"([{"material": {"brdf": "lambert", "smoothness": 0.5}}])"),
              "/objects/0/material/smoothness", 2, 47, "does not apply to brdf 'lambert'");
  // "brdf" 28-33, ':' 34, ' ' 35, value at 36.
  expectError(sceneWithObjects(R"([{"material": {"brdf": "ggx"}}])"), "/objects/0/material/brdf", 2, 36,
              "expected one of: lambert, srp; got 'ggx'");
  // "brdf" 28-33, ':' 34, ' ' 35, "srp" 36-40, ',' 41, "metallic" 43-52, ':' 53, ' ' 54, value 55.
  expectError(sceneWithObjects(R"([{"material": {"brdf": "srp", "metallic": 1.5}}])"),
              "/objects/0/material/metallic", 2, 55, "expected a number in [0, 1], got 1.5");
  // The legacy profile is diffuse only (SPEC 2).
  const std::string legacy =
      "{\"lightcts\": 1, \"image\": {}, \"camera\": {}, \"pipeline\": {\"profile\": \"legacy\"},\n"
      " \"objects\": [{}, {\"material\": {\"brdf\": \"srp\"}}],\n \"lights\": []}";
  // Line 2: ` "objects": [{}, {"material": {"brdf": "srp"}}]`: '{' 18, "material" 19-28, '{' 31,
  // "brdf" 32-37, ':' 38, ' ' 39, value at 40.
  expectError(legacy, "/objects/1/material/brdf", 2, 40, "brdf 'srp' is not available in the legacy profile");
}

}  // namespace
}  // namespace scene_input
