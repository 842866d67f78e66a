// The glTF import (SPEC 2.1) against values derived by hand from the
// generated models (suite/gltf/generate_models.py states each derivation),
// and its refusals of bad files (exit 2 through SceneLoadError).
#include "lighting/mesh.h"
#include "scene_input/gltf_import.h"
#include "scene_input/imported_mesh.h"
#include "scene_input/scene_loader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include <unistd.h>

namespace scene_input {
namespace {

using namespace lighting;

namespace fs = std::filesystem;

const fs::path kScenes = fs::path(LIGHTCTS_SOURCE_DIR) / "suite/scenes/gltf";
const double s = std::sqrt(0.5);

const Object& objectNamed(const Scene& scene, const std::string& name) {
  for (const Object& o : scene.objects)
    if (o.name == name) return o;
  throw std::runtime_error("no object " + name);
}

void expectNear(const Vec3& got, const Vec3& want, double eps = 1e-12) {
  EXPECT_NEAR(got.x, want.x, eps);
  EXPECT_NEAR(got.y, want.y, eps);
  EXPECT_NEAR(got.z, want.z, eps);
}

Vec3 faceNormal(const Mesh& m, std::size_t t) {
  const auto& tri = m.triangles[t];
  return glm::normalize(glm::cross(m.positions[tri.y] - m.positions[tri.x], m.positions[tri.z] - m.positions[tri.x]));
}

TEST(GltfImport, PlaneIsTheBuiltinPlaneBitForBit) {
  const Scene scene = loadSceneFile((kScenes / "plane-as-gltf.json").string());
  ASSERT_EQ(scene.objects.size(), 1u);
  EXPECT_EQ(scene.objects[0].name, "plane/0");
  const Mesh& imported = *scene.objects[0].mesh.imported;
  MeshSpec spec;
  spec.planeSizeX = spec.planeSizeZ = 8;
  spec.subdivisions = 4;
  const Mesh builtin = buildMesh(spec);
  EXPECT_EQ(imported.positions, builtin.positions);
  EXPECT_EQ(imported.normals, builtin.normals);
  EXPECT_EQ(imported.triangles, builtin.triangles);
  EXPECT_EQ(imported.trianglePiece, builtin.trianglePiece);
  // Hand values: vertex j*5+i at (-4+2i, 0, -4+2j); cell (0,0) is (0,5,6), (0,6,1).
  expectNear(imported.positions[7], Vec3(0, 0, -2), 0);
  EXPECT_EQ(imported.triangles[0], glm::u32vec3(0, 5, 6));
  EXPECT_EQ(imported.triangles[1], glm::u32vec3(0, 6, 1));
}

TEST(GltfImport, SphereAndBoxAreTheBuiltinsBitForBit) {
  const Scene sphere = loadSceneFile((kScenes / "sphere-as-gltf.json").string());
  MeshSpec sphereSpec;
  sphereSpec.type = MeshType::Sphere;
  sphereSpec.sphereRadius = 1;
  sphereSpec.sphereSegments = 24;
  sphereSpec.sphereRings = 12;
  const Mesh builtinSphere = buildMesh(sphereSpec);
  const Mesh& s1 = *sphere.objects.at(0).mesh.imported;
  EXPECT_EQ(s1.positions, builtinSphere.positions);
  EXPECT_EQ(s1.normals, builtinSphere.normals);
  EXPECT_EQ(s1.triangles, builtinSphere.triangles);
  EXPECT_EQ(s1.trianglePiece, builtinSphere.trianglePiece);
  EXPECT_EQ(s1.positions.size(), 325u);
  EXPECT_EQ(s1.triangles.size(), 528u);
  // The material mapping: roughness 0.375 is smoothness 0.625.
  EXPECT_EQ(sphere.objects[0].brdf, Brdf::Srp);
  EXPECT_EQ(sphere.objects[0].albedo, Vec3(0.75, 0.5, 0.25));
  EXPECT_EQ(sphere.objects[0].metallic, 0.25);
  EXPECT_EQ(sphere.objects[0].smoothness, 0.625);

  const Scene box = loadSceneFile((kScenes / "box-as-gltf.json").string());
  MeshSpec boxSpec;
  boxSpec.type = MeshType::Box;
  boxSpec.boxSize = Vec3(2, 1, 1.5);
  const Mesh builtinBox = buildMesh(boxSpec);
  const Mesh& b = *box.objects.at(0).mesh.imported;
  EXPECT_EQ(b.positions, builtinBox.positions);
  EXPECT_EQ(b.normals, builtinBox.normals);
  EXPECT_EQ(b.triangles, builtinBox.triangles);
  // Six flat faces are six smooth pieces, numbered in face order.
  EXPECT_EQ(b.trianglePiece, builtinBox.trianglePiece);
  // The legacy profile is diffuse only: lambert with the base colour.
  EXPECT_EQ(box.objects[0].brdf, Brdf::Lambert);
  EXPECT_EQ(box.objects[0].albedo, Vec3(0.5, 0.75, 1.0));
}

TEST(GltfImport, NodeHierarchyInDepthFirstOrderWithTheImportTransform) {
  const Scene scene = loadSceneFile((kScenes / "node-hierarchy.json").string());
  std::vector<std::string> names;
  for (const Object& o : scene.objects)
    if (o.mesh.type == MeshType::Imported) names.push_back(o.name);
  EXPECT_EQ(names, (std::vector<std::string>{"turned/0", "stretched/0", "leaning/0", "mirrored/0", "by-matrix/0",
                                             "grandchild/0"}));
  const Vec3 shift(0, 0, 0.5);  // the import's translate
  struct Expected {
    const char* name;
    Vec3 v[4];
    Vec3 normal;
  };
  const double e = std::sqrt(2.0) / 8, q = std::sqrt(2.0) / 4;
  const Expected expected[] = {
      {"turned/0", {{2, .5, .5}, {2, .5, -.5}, {2, 1.5, -.5}, {2, 1.5, .5}}, {1, 0, 0}},
      {"stretched/0", {{-3, .75, 0}, {-1, .75, 0}, {-1, 1.25, 0}, {-3, 1.25, 0}}, {0, 0, 1}},
      {"leaning/0", {{-3, 2 - e, q}, {-1, 2 - e, q}, {-1, 2 + e, -q}, {-3, 2 + e, -q}}, Vec3(0, 2, 1) / std::sqrt(5.0)},
      {"mirrored/0", {{.5, .5, -2}, {-.5, .5, -2}, {-.5, 1.5, -2}, {.5, 1.5, -2}}, {0, 0, 1}},
      {"by-matrix/0", {{-.5, 1, 2.5}, {.5, 1, 2.5}, {.5, 1, 1.5}, {-.5, 1, 1.5}}, {0, 1, 0}},
      {"grandchild/0", {{-.5, 2, 2.5}, {.5, 2, 2.5}, {.5, 2, 1.5}, {-.5, 2, 1.5}}, {0, 1, 0}},
  };
  for (const Expected& x : expected) {
    SCOPED_TRACE(x.name);
    const Mesh& m = *objectNamed(scene, x.name).mesh.imported;
    ASSERT_EQ(m.positions.size(), 4u);
    for (int v = 0; v < 4; ++v) expectNear(m.positions[v], x.v[v] + shift);
    for (int v = 0; v < 4; ++v) expectNear(m.normals[v], x.normal);
    // Front faces face the normal: a mirrored node's winding is reversed.
    for (std::size_t t = 0; t < m.triangles.size(); ++t) expectNear(faceNormal(m, t), x.normal);
  }
  const Mesh& mirrored = *objectNamed(scene, "mirrored/0").mesh.imported;
  EXPECT_EQ(mirrored.triangles[0], glm::u32vec3(0, 2, 1));
  EXPECT_EQ(mirrored.triangles[1], glm::u32vec3(0, 3, 2));
  // SPEC 2.1's bounds: the box of the world positions.
  const Mesh& turned = *objectNamed(scene, "turned/0").mesh.imported;
  expectNear(turned.boundsMin, Vec3(2, .5, 0), 1e-12);
  expectNear(turned.boundsMax, Vec3(2, 1.5, 1), 1e-12);
}

TEST(GltfImport, StripsAndFansBecomeTheirTrianglesAndPointsAreSkipped) {
  const Scene scene = loadSceneFile((kScenes / "strips-and-fans.json").string());
  const Mesh& strip = *objectNamed(scene, "strip/0").mesh.imported;
  const Vec3 stripWant[3][3] = {{{-3, 1, 0}, {-3, 0, 0}, {-2, 1, 0}},
                                {{-3, 0, 0}, {-2, 0, 0}, {-2, 1, 0}},
                                {{-2, 1, 0}, {-2, 0, 0}, {-1, 1, 0}}};
  ASSERT_EQ(strip.triangles.size(), 3u);
  for (int t = 0; t < 3; ++t) {
    const auto& tri = strip.triangles[t];
    expectNear(strip.positions[tri.x], stripWant[t][0], 0);
    expectNear(strip.positions[tri.y], stripWant[t][1], 0);
    expectNear(strip.positions[tri.z], stripWant[t][2], 0);
  }
  const Mesh& fan = *objectNamed(scene, "fan/0").mesh.imported;
  const Vec3 fanWant[3][3] = {{{3, 0, 0}, {3, 1, 0}, {1, 0, 0}},
                              {{3, 1, 0}, {2, 1.5, 0}, {1, 0, 0}},
                              {{2, 1.5, 0}, {1, 1, 0}, {1, 0, 0}}};
  ASSERT_EQ(fan.triangles.size(), 3u);
  for (int t = 0; t < 3; ++t) {
    const auto& tri = fan.triangles[t];
    expectNear(fan.positions[tri.x], fanWant[t][0], 0);
    expectNear(fan.positions[tri.y], fanWant[t][1], 0);
    expectNear(fan.positions[tri.z], fanWant[t][2], 0);
  }
  bool warned = false;
  for (const std::string& w : scene.warnings) warned |= w.find("/meshes/2/primitives/0/mode: points") != std::string::npos;
  EXPECT_TRUE(warned);
  for (const Object& o : scene.objects) EXPECT_NE(o.name, "points/0");
}

TEST(GltfImport, GlTfStripAndFanOrderAsTheSpecificationWritesIt) {
  const std::vector<std::uint32_t> five{10, 11, 12, 13, 14};
  EXPECT_EQ(trianglesOf(TriangleMode::Strip, five),
            (std::vector<glm::u32vec3>{{10, 11, 12}, {11, 13, 12}, {12, 13, 14}}));
  EXPECT_EQ(trianglesOf(TriangleMode::Fan, five), (std::vector<glm::u32vec3>{{11, 12, 10}, {12, 13, 10}, {13, 14, 10}}));
  // A repeated index (a strip's stitch) has no area and is left out.
  EXPECT_EQ(trianglesOf(TriangleMode::Strip, {0, 1, 1, 2}).size(), 0u);
}

TEST(GltfImport, FlatNormalsWhereTheFileGivesNone) {
  const Scene scene = loadSceneFile((kScenes / "flat-normals.json").string());
  const Mesh& roof = *objectNamed(scene, "roof/0").mesh.imported;
  ASSERT_EQ(roof.triangles.size(), 4u);
  ASSERT_EQ(roof.positions.size(), 12u);  // three vertices of its own per triangle
  const Vec3 want[4] = {{0, s, s}, {0, s, s}, {0, s, -s}, {0, s, -s}};
  for (int t = 0; t < 4; ++t)
    for (int k = 0; k < 3; ++k) expectNear(roof.normals[roof.triangles[t][k]], want[t]);
  // Two slopes, each one smooth piece.
  EXPECT_EQ(roof.trianglePiece, (std::vector<std::uint32_t>{0, 0, 1, 1}));
}

TEST(GltfImport, DoubleSidedMaterialAddsTheReversedBack) {
  const Scene scene = loadSceneFile((kScenes / "double-sided.json").string());
  const Mesh& two = *objectNamed(scene, "double-sided/0").mesh.imported;
  const Mesh& one = *objectNamed(scene, "single-sided/0").mesh.imported;
  EXPECT_EQ(one.triangles.size(), 2u);
  ASSERT_EQ(two.triangles.size(), 4u);
  for (int t = 0; t < 2; ++t) expectNear(faceNormal(two, t), Vec3(0, 1, 0));
  for (int t = 2; t < 4; ++t) {
    expectNear(faceNormal(two, t), Vec3(0, -1, 0));
    for (int k = 0; k < 3; ++k) expectNear(two.normals[two.triangles[t][k]], Vec3(0, -1, 0));
  }
  EXPECT_NE(two.trianglePiece[0], two.trianglePiece[2]);  // the back is its own surface
}

TEST(GltfImport, PunctualLightsMapAsSpec21Says) {
  const Scene scene = loadSceneFile((kScenes / "punctual-lights.json").string());
  ASSERT_EQ(scene.lights.size(), 4u);
  const Light& sun = scene.lights[0];
  EXPECT_EQ(sun.name, "sun");
  EXPECT_EQ(sun.type, LightType::Directional);
  expectNear(sun.direction, Vec3(0, -std::sqrt(3.0) / 2, -0.5));
  expectNear(sun.finalColor(), Vec3(2, 1, 0.5), 0);
  const Light& bulb = scene.lights[1];
  EXPECT_EQ(bulb.type, LightType::Point);
  expectNear(bulb.position, Vec3(1, 2, 0), 0);
  expectNear(bulb.finalColor(), Vec3(4, 4, 4), 0);  // no colour: white
  EXPECT_EQ(bulb.range, 5);
  const Light& spot = scene.lights[2];
  EXPECT_EQ(spot.type, LightType::Spot);
  expectNear(spot.position, Vec3(-1, 3, 1), 0);
  expectNear(spot.direction, Vec3(0, -1, 0));
  expectNear(spot.finalColor(), Vec3(1.5, 2.25, 3), 0);
  EXPECT_EQ(spot.range, 6);
  // Cone half-angles pi/4 and pi/8 are full cones of 90 and 45 degrees.
  EXPECT_NEAR(spot.spotAngleDeg, 90, 1e-12);
  ASSERT_TRUE(spot.innerSpotAngleDeg);
  EXPECT_NEAR(*spot.innerSpotAngleDeg, 45, 1e-12);
  const Light& lamp = scene.lights[3];
  EXPECT_EQ(lamp.name, "lamp");  // no light name: the node's
  expectNear(lamp.position, Vec3(0, 2, -2), 0);
  EXPECT_EQ(lamp.range, 4);  // none in the file: light_defaults.range
  EXPECT_EQ(lamp.mode, LightMode::Realtime);
}

TEST(GltfImport, GltfCameraAtItsNode) {
  const Scene scene = loadSceneFile((kScenes / "gltf-camera.json").string());
  EXPECT_EQ(scene.camera.projection, Projection::Perspective);
  expectNear(scene.camera.position, Vec3(0, 6, 6));
  expectNear(glm::normalize(scene.camera.target - scene.camera.position), Vec3(0, -s, -s));
  expectNear(scene.camera.up, Vec3(0, s, -s));
  EXPECT_NEAR(scene.camera.fovYDeg, 0.8 * 180 / std::numbers::pi, 1e-12);
  EXPECT_EQ(scene.camera.nearPlane, 0.1);
  EXPECT_EQ(scene.camera.farPlane, 50);
}

// --- refusals ---------------------------------------------------------------

class GltfRefusal : public ::testing::Test {
 protected:
  // A folder of its own: ctest runs this fixture's tests in parallel
  // processes, each writing model.gltf and scene.json.
  fs::path dir = fs::path(testing::TempDir()) /
                 ("lightcts-gltf-refusal-" + std::string(testing::UnitTest::GetInstance()->current_test_info()->name()) +
                  "-" + std::to_string(::getpid()));
  void SetUp() override { fs::create_directories(dir); }
  void TearDown() override { fs::remove_all(dir); }

  // Writes `gltf` beside a scene that imports it; the load must fail naming
  // the glTF file and `pointer`.
  void expectRefused(const std::string& gltf, const std::string& pointer, const std::string& words,
                     const std::string& importExtra = "") {
    const fs::path model = dir / "model.gltf";
    std::ofstream(model) << gltf;
    const fs::path scene = dir / "scene.json";
    std::ofstream(scene) << R"({"lightcts": 1, "image": {}, "camera": {}, "objects": [], "lights": [],
      "imports": [{"gltf": "model.gltf")" << importExtra << "}]}";
    try {
      loadSceneFile(scene.string());
      FAIL() << "loaded";
    } catch (const SceneLoadError& e) {
      EXPECT_EQ(e.error().file, model.string());
      EXPECT_EQ(e.error().jsonPath, pointer) << e.what();
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("imported by " + scene.string() + " at /imports/0"), std::string::npos);
    }
  }
};

// One triangle: positions (0,0,0), (1,0,0), (0,1,0) as float32 and indices
// 0, 1, 2 as unsigned bytes, in one 40-byte buffer (36 + 3, padded to 40).
std::string triangleGltf(const std::string& nodes = R"([{"mesh": 0}])", const std::string& indexBytes = "AAEC",
                         const std::string& extra = "") {
  // base64 of the 36 position bytes, then the index bytes (0x00 0x01 0x02) and a pad byte.
  const std::string positions = "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA";
  return R"({"asset": {"version": "2.0"}, "scenes": [{"nodes": [0]}], "nodes": )" + nodes + extra +
         R"(, "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0,0,0], "max": [1,1,0]},
                  {"bufferView": 1, "componentType": 5121, "count": 3, "type": "SCALAR"}],
    "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 3}],
    "buffers": [{"byteLength": 40, "uri": "data:application/octet-stream;base64,)" +
         positions + indexBytes + R"(AA=="}]})";
}

TEST_F(GltfRefusal, TheValidTriangleLoads) {
  const fs::path model = dir / "ok.gltf";
  std::ofstream(model) << triangleGltf();
  const Scene scene = loadSceneFile(model.string());  // a bare file
  ASSERT_EQ(scene.objects.size(), 1u);
  EXPECT_EQ(scene.objects[0].name, "#0/0");
  expectNear(scene.objects[0].mesh.imported->positions[1], Vec3(1, 0, 0), 0);
}

TEST_F(GltfRefusal, IndexOutOfRange) {
  // Index bytes 0x00 0x01 0x09: 9 >= 3 vertices.
  expectRefused(triangleGltf(R"([{"mesh": 0}])", "AAEJ"), "/accessors/1", "index 9 (element 2) is out of range");
}

TEST_F(GltfRefusal, NodeCycle) {
  expectRefused(triangleGltf(R"([{"mesh": 0, "children": [1]}, {"children": [0]}])"), "/nodes/1/children/0",
                "its own ancestor");
}

// Read by the same JSON reader as a scene file (scene_input/json_input.h).
TEST_F(GltfRefusal, ARepeatedKeyAsInASceneFile) {
  expectRefused(triangleGltf(R"([{"mesh": 0, "mesh": 0}])"), "/nodes/0/mesh", "duplicate key 'mesh'");
}

TEST_F(GltfRefusal, ANonFiniteLiteralAsInASceneFile) {
  const std::string gltf = triangleGltf(R"([{"mesh": 0, "translation": [0, NaN, 0]}])");
  expectRefused(gltf, "", "non-finite numbers (NaN, Infinity) are not allowed in a glTF file");
  // Where the literal starts, as FILE:LINE:COL like every error of a .gltf text.
  const std::size_t newline = gltf.rfind('\n', gltf.find("NaN"));
  const std::size_t line = 1 + std::size_t(std::count(gltf.begin(), gltf.begin() + std::ptrdiff_t(gltf.find("NaN")), '\n'));
  const std::size_t column = gltf.find("NaN") - (newline == std::string::npos ? 0 : newline + 1) + 1;
  try {
    loadSceneFile((dir / "scene.json").string());
  } catch (const SceneLoadError& e) {
    EXPECT_EQ(e.error().line, int(line)) << e.what();
    EXPECT_EQ(e.error().column, int(column)) << e.what();
  }
}

TEST_F(GltfRefusal, RequiredExtension) {
  expectRefused(triangleGltf(R"([{"mesh": 0}])", "AAEC", R"(, "extensionsRequired": ["KHR_draco_mesh_compression"])"),
                "/extensionsRequired/0", "lightcts does not read");
}

// A scene whose import of the one-triangle file (no lights) says `importExtra`
// must fail at `pointer` of the scene itself.
void expectSceneRefused(const fs::path& dir, const std::string& importExtra, const std::string& pointer,
                        const std::string& words) {
  std::ofstream(dir / "model.gltf") << triangleGltf();
  const fs::path scene = dir / "scene.json";
  std::ofstream(scene) << R"({"lightcts": 1, "image": {}, "camera": {}, "objects": [], "lights": [],
    "imports": [{"gltf": "model.gltf")" << importExtra << "}]}";
  try {
    loadSceneFile(scene.string());
    ADD_FAILURE() << "loaded with " << importExtra;
  } catch (const SceneLoadError& e) {
    EXPECT_EQ(e.error().file, scene.string());
    EXPECT_EQ(e.error().jsonPath, pointer) << e.what();
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

TEST_F(GltfRefusal, LightDefaultsOutOfRangeEvenWhereNoLightTakesThem) {
  expectSceneRefused(dir, R"(, "light_defaults": {"range": -1})", "/imports/0/light_defaults/range",
                     "expected a number > 0, got -1");
  expectSceneRefused(dir, R"(, "light_defaults": {"shadow_strength": 2})", "/imports/0/light_defaults/shadow_strength",
                     "expected a number in [0, 1], got 2");
}

TEST_F(GltfRefusal, LightDefaultsOnAnImportThatTakesNoLights) {
  for (const char* lights : {R"(, "lights": false)", R"(, "lights": "default-rig")"})
    expectSceneRefused(dir, std::string(lights) + R"(, "light_defaults": {"range": 5})", "/imports/0/light_defaults",
                       "this import takes none");
}

TEST_F(GltfRefusal, ALightWithoutRangeNeedsLightDefaults) {
  const std::string lights =
      R"(, "extensions": {"KHR_lights_punctual": {"lights": [{"type": "point"}]}})";
  expectRefused(triangleGltf(R"([{"mesh": 0, "extensions": {"KHR_lights_punctual": {"light": 0}}}])", "AAEC", lights),
                "/extensions/KHR_lights_punctual/lights/0", "no range");
}

TEST_F(GltfRefusal, BufferTooShortForTheView) {
  std::string gltf = triangleGltf();
  gltf.replace(gltf.find(R"("byteOffset": 36, "byteLength": 3)"), 33, R"("byteOffset": 36, "byteLength": 30)");
  expectRefused(gltf, "/bufferViews/1", "runs past the end of buffer 0");
}

TEST_F(GltfRefusal, WrongTypeWhereTheModelReads) {
  std::string gltf = triangleGltf();
  gltf.replace(gltf.find(R"("scenes": [{"nodes": [0]}])"), 26, R"("scenes": [{"nodes": [0]}], "scene": "hello")");
  expectRefused(gltf, "/scene", "expected an index into scenes");
}

TEST_F(GltfRefusal, LineAndColumnOfATextFile) {
  const fs::path model = dir / "model.gltf";
  std::ofstream(model) << triangleGltf(R"([{"mesh": 7}])");
  const fs::path scene = dir / "scene.json";
  std::ofstream(scene) << R"({"lightcts": 1, "image": {}, "camera": {}, "objects": [], "lights": [],
      "imports": [{"gltf": "model.gltf"}]})";
  try {
    loadSceneFile(scene.string());
    FAIL();
  } catch (const SceneLoadError& e) {
    EXPECT_EQ(e.error().jsonPath, "/nodes/0/mesh");
    EXPECT_EQ(e.error().line, 1);
    EXPECT_GT(e.error().column, 1);
  }
}

}  // namespace
}  // namespace scene_input
