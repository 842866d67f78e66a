// Reads a scene file into lighting::Scene and rejects everything SPEC section 2
// calls an error. docs/scene-format.md lists every key with its type, default
// and range, and the rules SPEC leaves open that this file decides.
#include "scene_input/scene_loader.h"

#include "imaging/image_files.h"

#include "lighting/scene_words.h"
#include "lighting/transform.h"
#include "lighting/visible_lights.h"
#include "scene_input/gltf_import.h"
#include "scene_input/gltf_scene_mapping.h"
#include "scene_input/json_describe.h"
#include "scene_input/json_cursor.h"
#include "scene_input/json_input.h"
#include "scene_input/json_locations.h"
#include "scene_input/look_at.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numbers>
#include <optional>
#include <span>
#include <sstream>
#include <tuple>
#include <utility>

namespace scene_input {

using namespace lighting;  // the model this folder reads scenes into

std::string SceneError::format() const {
  std::string text = file;
  if (line > 0) text += ":" + std::to_string(line) + ":" + std::to_string(column);
  text += ": ";
  if (!jsonPath.empty()) text += jsonPath + ": ";
  return text + message;
}

SceneLoadError::SceneLoadError(SceneError error)
    : std::runtime_error(error.format()), error_(std::move(error)) {}

namespace {

// Ordered, so that of several unknown keys the first one in the file is named.
using Json = nlohmann::ordered_json;
using Keys = std::span<const std::string_view>;

// The largest integer a JSON number carries exactly through a double.
constexpr long long kMaxExactInteger = 9007199254740992LL;  // 2^53
// 8192 is the largest image side, 4096 the largest mesh tessellation and
// lightmap: bounds that keep memory finite while leaving room for any test.
constexpr long long kMaxImageSide = 8192;
constexpr long long kMaxTessellation = 4096;
constexpr long long kMaxLightmapResolution = 4096;
constexpr long long kMaxFrames = 10000;
// glTF indices (a scene, a camera) beyond this are no file's.
constexpr long long kMaxGltfIndex = 1 << 30;

// The one place that builds errors: every failure of loading goes through here.
[[noreturn]] void throwSceneError(std::string file, std::string jsonPath, TextPosition where,
                                  std::string message) {
  throw SceneLoadError(SceneError{std::move(file), std::move(jsonPath), where.line, where.column,
                                  std::move(message)});
}

std::string joinKeys(Keys keys) {
  std::string joined;
  for (const std::string_view key : keys) {
    if (!joined.empty()) joined += ", ";
    joined += key;
  }
  return joined;
}

bool contains(Keys keys, std::string_view key) { return std::find(keys.begin(), keys.end(), key) != keys.end(); }

template <typename T>
using Choice = SceneWord<T>;  // lighting/scene_words.h


// The keys each object may hold, in the order SPEC 2's example lists them.
constexpr std::array<std::string_view, 12> kSceneKeys{"lightcts", "name",   "description", "image",
                                                      "camera",   "pipeline", "ambient",   "objects",
                                                      "lights",   "frames",   "expect",    "imports"};
// SPEC 2.1: an import of a glTF file, and what its lights take from the scene.
// An import's "lights": "default-rig" (SPEC 2.1: an import may ask for the rig).
constexpr std::string_view kDefaultRigWord = "default-rig";
constexpr std::array<std::string_view, 6> kImportKeys{"gltf",      "scene",  "transform",
                                                      "materials", "lights", "light_defaults"};
constexpr std::array<std::string_view, 7> kLightDefaultsKeys{"range",      "mode",         "shadows", "shadow_strength",
                                                             "shadow_map", "bake_falloff", "cookie"};
constexpr std::array<std::string_view, 1> kGltfCameraKeys{"gltf_camera"};
constexpr std::array<std::string_view, 2> kImageKeys{"width", "height"};
constexpr std::array<std::string_view, 8> kCameraKeys{"position",  "target", "up",   "projection",
                                                      "fov_y_deg", "height", "near", "far"};
constexpr std::array<std::string_view, 7> kPerspectiveKeys{"position",  "target", "up", "projection",
                                                           "fov_y_deg", "near",   "far"};
constexpr std::array<std::string_view, 7> kOrthographicKeys{"position", "target", "up", "projection",
                                                            "height",   "near",   "far"};
constexpr std::array<std::string_view, 6> kPipelineKeys{"profile",         "path",             "lights_per_object",
                                                        "deferred_buffer", "fade_last_lights", "shadow_distance"};
constexpr std::array<std::string_view, 6> kObjectKeys{"name",     "mesh",   "transform",
                                                      "material", "static", "lightmap_resolution"};
constexpr std::array<std::string_view, 6> kMeshKeys{"type", "size", "subdivisions", "radius", "segments", "rings"};
constexpr std::array<std::string_view, 3> kPlaneKeys{"type", "size", "subdivisions"};
constexpr std::array<std::string_view, 4> kSphereKeys{"type", "radius", "segments", "rings"};
constexpr std::array<std::string_view, 2> kBoxKeys{"type", "size"};
constexpr std::array<std::string_view, 3> kTransformKeys{"translate", "rotate_deg", "scale"};
constexpr std::array<std::string_view, 4> kMaterialKeys{"albedo", "brdf", "metallic", "smoothness"};
constexpr std::array<std::string_view, 2> kAlbedoOnly{"albedo", "brdf"};
constexpr std::array<std::string_view, 15> kLightKeys{
    "name",      "type", "position", "direction",       "range",        "spot_angle_deg", "inner_spot_angle_deg", "color",
    "intensity", "mode", "shadows",  "shadow_strength", "bake_falloff", "cookie",         "shadow_map"};
// SPEC 2 and 3.9: a shadow map's keys, all of them, then those of each light type.
constexpr std::array<std::string_view, 7> kShadowMapKeys{"resolution", "filter", "depth_bias", "normal_bias",
                                                         "near",       "center", "extent"};
constexpr std::array<std::string_view, 6> kDirectionalShadowMapKeys{"resolution",  "filter", "depth_bias",
                                                                    "normal_bias", "center", "extent"};
constexpr std::array<std::string_view, 5> kLocalShadowMapKeys{"resolution", "filter", "depth_bias", "normal_bias",
                                                              "near"};
constexpr int kMinShadowMapResolution = 16;
constexpr int kMaxShadowMapResolution = 4096;
// SPEC 2: a shadowed spot needs spot_angle_deg <= 170 (the projection's tangent).
constexpr double kWidestShadowedSpotDeg = 170;
constexpr std::array<std::string_view, 3> kCookieKeys{"image", "size", "cube"};
constexpr std::array<std::string_view, 2> kDirectionalCookieKeys{"image", "size"};
constexpr std::array<std::string_view, 1> kSpotCookieKeys{"image"};
constexpr std::array<std::string_view, 1> kPointCookieKeys{"cube"};
// SPEC 2: a cookie needs a spot no wider than this (the projection's tangent).
constexpr double kWidestCookieSpotDeg = 170;
constexpr std::size_t kCubeFaces = 6;
constexpr std::array<std::string_view, 2> kFramesKeys{"count", "camera_path"};
constexpr std::array<std::string_view, 2> kKeyframeKeys{"position", "target"};
constexpr std::array<std::string_view, 4> kExpectKeys{"tolerance_scale", "max_failing_pixels", "expect_fail",
                                                     "against"};

constexpr const auto& kProjections = kProjectionWords;
constexpr std::array<Choice<MeshType>, 3> kMeshTypes{
    {{"plane", MeshType::Plane}, {"sphere", MeshType::Sphere}, {"box", MeshType::Box}}};
constexpr const auto& kLightTypes = kLightTypeWords;
constexpr std::array<Choice<ShadowFilter>, 3> kShadowFilters{{{"hard", ShadowFilter::Hard},
                                                              {"bilinear", ShadowFilter::Bilinear},
                                                              {"tent3x3", ShadowFilter::Tent3x3}}};
constexpr std::array<Choice<LightMode>, 3> kLightModes{
    {{"realtime", LightMode::Realtime}, {"mixed", LightMode::Mixed}, {"baked", LightMode::Baked}}};
constexpr std::array<Choice<BakeFalloff>, 3> kBakeFalloffs{{{"inverse_squared", BakeFalloff::InverseSquared},
                                                            {"inverse_squared_no_range", BakeFalloff::InverseSquaredNoRange},
                                                            {"legacy", BakeFalloff::Legacy}}};
constexpr std::array<Choice<Brdf>, 2> kBrdfs{{{"lambert", Brdf::Lambert}, {"srp", Brdf::Srp}}};
constexpr std::array<Choice<Profile>, 2> kProfiles{{{"srp", Profile::Srp}, {"legacy", Profile::Legacy}}};
constexpr std::array<Choice<RenderPath>, 2> kRenderPaths{
    {{"forward", RenderPath::Forward}, {"deferred", RenderPath::Deferred}}};
constexpr const auto& kDeferredBuffers = kDeferredBufferWords;
// Extension of SPEC 2 (docs/scene-format.md, `expect.against`).
constexpr std::array<Choice<CompareAgainst>, 2> kCompareAgainst{
    {{"reference", CompareAgainst::Reference}, {"realtime", CompareAgainst::Realtime}}};

using Node = JsonCursor<Json>;

// Walks the parsed document; holds the text only to find line and column when
// something is wrong.
class SceneReader {
 public:
  SceneReader(std::string_view text, std::string file) : text_(text), file_(std::move(file)) {}

  Scene readScene(const Json& document) const {
    const Node root = Node::root(document);
    expectObject(root);
    readFormatVersion(root);
    checkKeys(root, kSceneKeys);
    for (const std::string_view key : {"image", "camera", "objects", "lights"}) requireMember(root, key);

    Scene scene;
    scene.name = std::filesystem::path(file_).stem().string();
    if (auto name = member(root, "name")) scene.name = readString(*name);
    if (auto description = member(root, "description")) scene.description = readString(*description);
    scene.image = readImage(*member(root, "image"));
    if (auto pipeline = member(root, "pipeline")) scene.pipeline = readPipeline(*pipeline);
    // SPEC 2.1: imports are read before the camera, which may be one of theirs.
    std::vector<Import> imports;
    if (auto list = member(root, "imports")) imports = readImports(*list, scene.pipeline.profile);
    scene.camera = readCamera(*member(root, "camera"), imports);
    if (auto ambient = member(root, "ambient")) scene.ambient = readVec3(*ambient, atLeast(0));
    scene.objects = readArray(*member(root, "objects"), &SceneReader::readObject);
    if (scene.pipeline.profile == Profile::Legacy) rejectSrpMaterials(*member(root, "objects"), scene.objects);
    scene.lights = readArray(*member(root, "lights"), &SceneReader::readLight);
    // Imported objects and lights follow the file's own (SPEC 2.1); an
    // import that asks for the default rig gets it from its content's bounds
    // and the scene's camera, and its ambient where the scene gives none.
    for (Import& import : imports) {
      for (Object& object : import.objects) scene.objects.push_back(std::move(object));
      for (Light& light : import.lights) scene.lights.push_back(std::move(light));
      if (import.defaultRig) lightByDefaultRig(scene, import.content, !member(root, "ambient"));
      for (std::string& warning : import.content.warnings) scene.warnings.push_back(std::move(warning));
    }
    if (auto frames = member(root, "frames")) scene.frames = readFrames(*frames, scene.camera);
    if (auto expect = member(root, "expect")) scene.expect = readExpectation(*expect);
    return scene;
  }

 private:
  // --- errors -------------------------------------------------------------

  [[noreturn]] void fail(const Node& node, std::string message) const {
    failAt(node.pointer, node.pointer, JsonLocationTarget::Value, std::move(message));
  }

  // For an unknown key the key itself is the place to look, not its value.
  [[noreturn]] void failOnKey(const Node& node, std::string message) const {
    failAt(node.pointer, node.pointer, JsonLocationTarget::Key, std::move(message));
  }

  [[noreturn]] void failAt(const std::string& pointer, const std::string& locatedAt, JsonLocationTarget target,
                           std::string message) const {
    const TextPosition where = locateJsonPointer(text_, locatedAt, target).value_or(TextPosition{});
    throwSceneError(file_, pointer, where, std::move(message));
  }

  // --- objects and keys -----------------------------------------------------

  void expectObject(const Node& node) const {
    if (auto problem = kindProblem(node.value, JsonKind::Object)) fail(node, *problem);
  }

  static std::optional<Node> member(const Node& object, std::string_view key) { return object.member(key); }

  // A missing key has no place of its own, so the error points at the object that lacks it.
  void requireMember(const Node& object, std::string_view key) const {
    if (object.value.contains(key)) return;
    failAt(object.pointerTo(key), object.pointer, JsonLocationTarget::Value,
           "missing required key '" + std::string(key) + "'");
  }

  // Keys that belong to another variant of the object (a sphere's radius on a
  // plane) get a message of their own instead of "unknown key".
  struct OtherVariants {
    Keys keys;
    std::string chosen;  // e.g. "mesh type 'plane'"
  };

  void checkKeys(const Node& object, Keys allowed, const OtherVariants* others = nullptr) const {
    for (const auto& item : object.value.items()) {
      const std::string& key = item.key();
      if (contains(allowed, key)) continue;
      const Node node = object.item(key, item.value());
      if (others && contains(others->keys, key)) {
        failOnKey(node, "key '" + key + "' does not apply to " + others->chosen);
      }
      failOnKey(node, "unknown key '" + key + "'; expected one of: " + joinKeys(allowed));
    }
  }

  template <typename T>
  std::vector<T> readArray(const Node& node, T (SceneReader::*readElement)(const Node&, std::size_t) const) const {
    if (auto problem = kindProblem(node.value, JsonKind::Array)) fail(node, *problem);
    std::vector<T> elements;
    elements.reserve(node.value.size());
    for (std::size_t i = 0; i < node.value.size(); ++i) {
      elements.push_back((this->*readElement)(node.element(i), i));
    }
    return elements;
  }

  // --- scalars --------------------------------------------------------------

  double readNumber(const Node& node, const NumberBounds& bounds = kAnyNumber) const {
    if (auto problem = numberProblem(node.value, bounds)) fail(node, *problem);
    return node.value.get<double>();
  }

  long long readInteger(const Node& node, long long min, long long max) const {
    if (auto problem = integerProblem(node.value, min, max)) fail(node, *problem);
    return static_cast<long long>(node.value.get<double>());
  }

  int readInt(const Node& node, long long min, long long max) const {
    return static_cast<int>(readInteger(node, min, max));
  }

  bool readBool(const Node& node) const {
    if (auto problem = kindProblem(node.value, JsonKind::Boolean)) fail(node, *problem);
    return node.value.get<bool>();
  }

  std::string readString(const Node& node) const {
    if (auto problem = kindProblem(node.value, JsonKind::String)) fail(node, *problem);
    return node.value.get<std::string>();
  }

  template <typename T, std::size_t N>
  T readChoice(const Node& node, const std::array<Choice<T>, N>& choices) const {
    std::string names;
    for (const Choice<T>& choice : choices) names += (names.empty() ? "" : ", ") + std::string(choice.name);
    if (!node.value.is_string()) fail(node, "expected one of: " + names + "; got " + describeJsonType(node.value));
    const std::string text = node.value.get<std::string>();
    for (const Choice<T>& choice : choices) {
      if (choice.name == text) return choice.value;
    }
    fail(node, "expected one of: " + names + "; got '" + text + "'");
  }

  Vec3 readVec3(const Node& node, const NumberBounds& bounds = kAnyNumber) const {
    if (!node.value.is_array() || node.value.size() != 3) {
      fail(node, "expected an array of 3 numbers, got " + describeJsonTypeAndLength(node.value));
    }
    const auto element = [&](std::size_t i) {
      return readNumber(node.element(i), bounds);
    };
    return Vec3{element(0), element(1), element(2)};  // braces: evaluated in order, so the first bad element is named
  }

  // --- scene parts ----------------------------------------------------------

  void readFormatVersion(const Node& root) const {
    requireMember(root, "lightcts");
    const Node version = *member(root, "lightcts");
    if (!version.value.is_number()) fail(version, "expected the format version 1, got " + describeJsonType(version.value));
    const double number = version.value.get<double>();
    if (number != 1.0) fail(version, "unsupported format version " + formatJsonNumber(number) + "; this loader reads version 1");
  }

  ImageSize readImage(const Node& node) const {
    expectObject(node);
    checkKeys(node, kImageKeys);
    ImageSize image;
    if (auto width = member(node, "width")) image.width = readInt(*width, 1, kMaxImageSide);
    if (auto height = member(node, "height")) image.height = readInt(*height, 1, kMaxImageSide);
    return image;
  }

  // --- imports (SPEC 2.1) ---------------------------------------------------

  struct Import {
    GltfImportRequest request;
    GltfContent content;
    std::vector<Object> objects;
    std::vector<Light> lights;
    bool defaultRig = false;  // "lights": "default-rig": lit by the rig, placed once the camera is known
  };

  std::vector<Import> readImports(const Node& node, Profile profile) const {
    if (!node.value.is_array()) fail(node, "expected an array of imports, got " + describeJsonType(node.value));
    std::vector<Import> imports;
    for (std::size_t i = 0; i < node.value.size(); ++i)
      imports.push_back(readImport(node.element(i), profile));
    return imports;
  }

  Import readImport(const Node& node, Profile profile) const {
    expectObject(node);
    checkKeys(node, kImportKeys);
    requireMember(node, "gltf");
    Import import;
    import.request.file = (std::filesystem::path(file_).parent_path() / readString(*member(node, "gltf"))).string();
    if (auto scene = member(node, "scene")) import.request.scene = readInt(*scene, 0, kMaxGltfIndex);
    if (auto transform = member(node, "transform")) import.request.transform = importMatrix(readTransform(*transform));
    // The material every imported object gets instead of the file's, when given.
    std::optional<Object> material;
    if (auto materials = member(node, "materials")) {
      if (!materials->value.is_string()) {
        material.emplace();
        readMaterial(*materials, *material);
        if (profile == Profile::Legacy && material->brdf == Brdf::Srp)
          fail(*member(*materials, "brdf"), "brdf 'srp' is not available in the legacy profile (SPEC 2)");
      } else if (materials->value.get<std::string>() != "gltf") {
        fail(*materials, "expected \"gltf\" or a material object, got '" + materials->value.get<std::string>() + "'");
      }
    }
    bool takeLights = true;
    if (auto lights = member(node, "lights")) {
      if (lights->value.is_string()) {
        if (lights->value.get<std::string>() != kDefaultRigWord)
          fail(*lights, "expected true, false or \"" + std::string(kDefaultRigWord) + "\", got '" +
                            lights->value.get<std::string>() + "'");
        takeLights = false;
        import.defaultRig = true;
      } else {
        takeLights = readBool(*lights);
      }
    }
    std::optional<LightDefaults> defaults;
    if (auto defaultsNode = member(node, "light_defaults")) {
      expectObject(*defaultsNode);
      checkKeys(*defaultsNode, kLightDefaultsKeys);
      if (!takeLights)
        failOnKey(*defaultsNode, "light_defaults sets the imported file's lights, and this import takes none");
      defaults = readLightDefaults(*defaultsNode);
    }
    const std::string context = "imported by " + file_ + " at " + node.pointer;
    try {
      import.content = importGltf(import.request);
    } catch (const GltfError& error) {
      throwAsSceneError(error, context);
    }
    for (const ImportedPrimitive& primitive : import.content.primitives)
      import.objects.push_back(sceneObject(primitive, material, profile));
    if (takeLights)
      for (const ImportedLight& light : import.content.lights)
        import.lights.push_back(sceneLight(light, import.content, defaults ? &*defaults : nullptr, std::nullopt, context));
    return import;
  }

  // SPEC 1's transform as a matrix: translate, then R, then uniform scale.
  static glm::dmat4 importMatrix(const Transform& t) {
    const ObjectTransform o = objectTransform(t);
    glm::dmat4 m(glm::dmat3(o.rotation) * o.scale);
    m[3] = glm::dvec4(o.translate, 1.0);
    return m;
  }

  // light_defaults (an object of its keys), read once, whether or not the file has lights (a value
  // out of range is an error even where nothing takes it). A cookie and a
  // shadow map depend on the light's type: read with each light, as a scene
  // light's keys would be.
  LightDefaults readLightDefaults(const Node& node) const {
    LightDefaults defaults;
    if (auto range = member(node, "range")) defaults.range = readNumber(*range, above(0));
    if (auto mode = member(node, "mode")) defaults.mode = readChoice(*mode, kLightModes);
    if (auto shadows = member(node, "shadows")) defaults.shadows = readBool(*shadows);
    if (auto strength = member(node, "shadow_strength")) defaults.shadowStrength = readNumber(*strength, closed(0, 1));
    if (auto falloff = member(node, "bake_falloff")) defaults.bakeFalloff = readChoice(*falloff, kBakeFalloffs);
    // A cookie or a shadow map (the default one, where shadows are on) is
    // checked for each light's type; without them nothing is read per light.
    if (member(node, "cookie") || member(node, "shadow_map") || defaults.shadows.value_or(false))
      defaults.perLight = [this, node](Light& light) {
        if (auto cookie = member(node, "cookie")) light.cookie = readCookie(*cookie, light);
        readShadowMap(node, light);
      };
    return defaults;
  }

  // SPEC 2.1 `camera: {"gltf_camera": N}`: the first import's camera N.
  Camera readGltfCamera(const Node& node, const std::vector<Import>& imports) const {
    checkKeys(node, kGltfCameraKeys);
    const Node index = *member(node, "gltf_camera");
    if (imports.empty()) fail(index, "gltf_camera needs an import (SPEC 2.1); the scene has none");
    const GltfContent& content = imports.front().content;
    const int n = readInt(index, 0, kMaxGltfIndex);
    if (std::size_t(n) >= content.cameras.size() || !content.cameras[std::size_t(n)]) {
      fail(index, "the first import has no camera " + std::to_string(n) + " on a node of its scene (it has " +
                      std::to_string(content.cameras.size()) + " cameras)");
    }
    const auto camera = sceneCamera(*content.cameras[std::size_t(n)], content);
    if (!camera) fail(index, "glTF camera " + std::to_string(n) + " has no usable view (its up is along its view direction)");
    return *camera;
  }

  Camera readCamera(const Node& node, const std::vector<Import>& imports) const {
    expectObject(node);
    if (node.value.contains("gltf_camera")) return readGltfCamera(node, imports);
    Camera camera;
    if (auto projection = member(node, "projection")) camera.projection = readChoice(*projection, kProjections);
    // fov_y_deg on an orthographic camera (the default) would be silently
    // ignored; it is far more likely a missing "projection": "perspective".
    const bool perspective = camera.projection == Projection::Perspective;
    const OtherVariants others{kCameraKeys,
                               "projection '" + std::string(wordOf(kProjections, camera.projection)) + "'"};
    checkKeys(node, perspective ? Keys(kPerspectiveKeys) : Keys(kOrthographicKeys), &others);

    if (auto fov = member(node, "fov_y_deg")) camera.fovYDeg = readNumber(*fov, {0, true, 180, true});
    if (auto height = member(node, "height")) camera.orthoHeight = readNumber(*height, above(0));
    readClipPlanes(node, camera);
    readLookAt(node, camera);
    return camera;
  }

  void readLookAt(const Node& node, Camera& camera) const {
    const auto position = member(node, "position");
    const auto target = member(node, "target");
    const auto up = member(node, "up");
    if (position) camera.position = readVec3(*position);
    if (target) camera.target = readVec3(*target);
    if (up) camera.up = readVec3(*up);
    // The defaults make a valid lookAt, so a check fails only when one of
    // these was given; the error names the most specific one.
    if (up && !unitVector(camera.up)) fail(*up, "up must not be the zero vector");
    const auto problem = lookAtProblem(camera.position, camera.target, camera.up);
    if (!problem) return;
    const std::optional<Node>& culprit = (*problem == LookAtProblem::UpParallel && up) ? up : target ? target : position;
    fail(*culprit, describe(*problem, camera.up));
  }

  void readClipPlanes(const Node& node, Camera& camera) const {
    const auto nearNode = member(node, "near");
    const auto farNode = member(node, "far");
    if (nearNode) camera.nearPlane = readNumber(*nearNode, above(0));
    if (farNode) camera.farPlane = readNumber(*farNode, above(0));
    if (camera.farPlane > camera.nearPlane) return;
    if (farNode) {
      fail(*farNode, "expected far > near (" + formatJsonNumber(camera.nearPlane) + "), got " +
                         formatJsonNumber(camera.farPlane));
    }
    fail(*nearNode, "expected near < far (" + formatJsonNumber(camera.farPlane) + ", the default), got " +
                        formatJsonNumber(camera.nearPlane));
  }

  static std::string describe(LookAtProblem problem, const Vec3& up) {
    if (problem == LookAtProblem::SamePoint) return "target must differ from position";
    return "up [" + formatJsonNumber(up.x) + ", " + formatJsonNumber(up.y) + ", " + formatJsonNumber(up.z) +
           "] is parallel to the view direction (target - position)";
  }

  Pipeline readPipeline(const Node& node) const {
    expectObject(node);
    checkKeys(node, kPipelineKeys);
    Pipeline pipeline;
    if (auto profile = member(node, "profile")) pipeline.profile = readChoice(*profile, kProfiles);
    if (auto path = member(node, "path")) pipeline.path = readChoice(*path, kRenderPaths);
    if (auto perObject = member(node, "lights_per_object")) pipeline.lightsPerObject = readBool(*perObject);
    if (auto buffer = member(node, "deferred_buffer")) pipeline.deferredBuffer = readChoice(*buffer, kDeferredBuffers);
    // Extension (docs/model.md): at most the profile's budget of point/spot
    // lights can fade; the profile may come after this key, so it is read first.
    if (auto fade = member(node, "fade_last_lights")) {
      const bool legacy = pipeline.profile == Profile::Legacy;
      const int most = legacy ? kLegacyMaxLights : kSrpMaxOtherLights;
      const int count = readInt(*fade, 0, kSrpMaxOtherLights);
      if (count > most) {
        fail(*fade, "expected an integer in [0, " + std::to_string(most) + "] (the legacy profile keeps " +
                        std::to_string(most) + " lights), got " + std::to_string(count));
      }
      pipeline.fadeLastLights = count;
    }
    if (auto distance = member(node, "shadow_distance")) pipeline.shadowDistance = readNumber(*distance, atLeast(0));
    return pipeline;
  }

  Object readObject(const Node& node, std::size_t index) const {
    expectObject(node);
    checkKeys(node, kObjectKeys);
    Object object;
    object.name = "object" + std::to_string(index);
    if (auto name = member(node, "name")) object.name = readString(*name);
    if (auto mesh = member(node, "mesh")) object.mesh = readMesh(*mesh);
    if (auto transform = member(node, "transform")) object.transform = readTransform(*transform);
    if (auto material = member(node, "material")) readMaterial(*material, object);
    if (auto isStatic = member(node, "static")) object.isStatic = readBool(*isStatic);
    if (auto resolution = member(node, "lightmap_resolution")) {
      object.lightmapResolution = readInt(*resolution, 0, kMaxLightmapResolution);
      if (object.lightmapResolution > 0 && object.mesh.type != MeshType::Plane) {
        fail(*resolution, "lightmaps are only supported on planes (SPEC 2); this mesh is a " +
                              std::string(wordOf(kMeshTypes, object.mesh.type)));
      }
    }
    return object;
  }

  MeshSpec readMesh(const Node& node) const {
    expectObject(node);
    MeshSpec mesh;
    if (auto type = member(node, "type")) mesh.type = readChoice(*type, kMeshTypes);
    const OtherVariants others{kMeshKeys, "mesh type '" + std::string(wordOf(kMeshTypes, mesh.type)) + "'"};
    switch (mesh.type) {
      case MeshType::Plane:
        checkKeys(node, kPlaneKeys, &others);
        if (auto size = member(node, "size")) readPlaneSize(*size, mesh);
        if (auto subdivisions = member(node, "subdivisions")) {
          mesh.subdivisions = readInt(*subdivisions, 1, kMaxTessellation);
        }
        break;
      case MeshType::Sphere:
        checkKeys(node, kSphereKeys, &others);
        if (auto radius = member(node, "radius")) mesh.sphereRadius = readNumber(*radius, above(0));
        if (auto segments = member(node, "segments")) mesh.sphereSegments = readInt(*segments, 3, kMaxTessellation);
        if (auto rings = member(node, "rings")) mesh.sphereRings = readInt(*rings, 2, kMaxTessellation);
        break;
      case MeshType::Box:
        checkKeys(node, kBoxKeys, &others);
        if (auto size = member(node, "size")) mesh.boxSize = readVec3(*size, above(0));
        break;
      case MeshType::Imported:  // not a scene-file type: kMeshTypes cannot name it
        break;
    }
    return mesh;
  }

  void readPlaneSize(const Node& node, MeshSpec& mesh) const {
    std::tie(mesh.planeSizeX, mesh.planeSizeZ) = readPositivePair(node, "[sx, sz]");
  }

  // Two numbers > 0 (a plane's or a directional cookie's size); `form` names
  // them in the message, e.g. "[sx, sz]".
  std::pair<double, double> readPositivePair(const Node& node, std::string_view form) const {
    if (!node.value.is_array() || node.value.size() != 2) {
      fail(node, "expected " + std::string(form) + ", an array of 2 numbers, got " + describeJsonTypeAndLength(node.value));
    }
    return {readNumber({node.value[0], node.pointer + "/0"}, above(0)),
            readNumber({node.value[1], node.pointer + "/1"}, above(0))};
  }

  Transform readTransform(const Node& node) const {
    expectObject(node);
    checkKeys(node, kTransformKeys);
    Transform transform;
    if (auto translate = member(node, "translate")) transform.translate = readVec3(*translate);
    if (auto rotate = member(node, "rotate_deg")) transform.rotateDeg = readVec3(*rotate);
    if (auto scale = member(node, "scale")) transform.scale = readScale(*scale);
    return transform;
  }

  // SPEC 1 allows uniform scale only; [a, a, a] is accepted as the same thing.
  double readScale(const Node& node) const {
    if (!node.value.is_array()) return readNumber(node, above(0));
    const Vec3 scale = readVec3(node, above(0));
    if (scale.x != scale.y || scale.x != scale.z) {
      fail(node, "non-uniform scale is not part of the model (SPEC 1); give one number or three equal ones");
    }
    return scale.x;
  }

  void readMaterial(const Node& node, Object& object) const {
    expectObject(node);
    if (auto brdf = member(node, "brdf")) object.brdf = readChoice(*brdf, kBrdfs);
    // SPEC 2: metallic and smoothness belong to the srp BRDF; on a Lambert
    // material they would be silently ignored.
    if (object.brdf == Brdf::Lambert) {
      const OtherVariants others{kMaterialKeys, "brdf 'lambert' (metallic and smoothness need \"brdf\": \"srp\")"};
      checkKeys(node, kAlbedoOnly, &others);
    } else {
      checkKeys(node, kMaterialKeys);
    }
    if (auto albedo = member(node, "albedo")) object.albedo = readVec3(*albedo, closed(0, 1));
    if (auto metallic = member(node, "metallic")) object.metallic = readNumber(*metallic, closed(0, 1));
    if (auto smoothness = member(node, "smoothness")) object.smoothness = readNumber(*smoothness, closed(0, 1));
  }

  // SPEC 2: the legacy profile (the older chapter) is diffuse only.
  void rejectSrpMaterials(const Node& objects, const std::vector<Object>& read) const {
    for (std::size_t i = 0; i < read.size(); ++i) {
      if (read[i].brdf != Brdf::Srp) continue;
      const Node object = objects.element(i);
      const Node material = *member(object, "material");
      fail(*member(material, "brdf"),
           "brdf 'srp' is not available in the legacy profile (the older forward chapter is diffuse only, SPEC 2)");
    }
  }

  Light readLight(const Node& node, std::size_t index) const {
    expectObject(node);
    // Every light key is accepted on every type, so a scene can switch a
    // light's type without deleting keys; the unused ones are ignored.
    checkKeys(node, kLightKeys);
    Light light;
    light.name = "light" + std::to_string(index);
    if (auto name = member(node, "name")) light.name = readString(*name);
    if (auto type = member(node, "type")) light.type = readLightType(*type);
    if (auto position = member(node, "position")) light.position = readVec3(*position);
    if (auto direction = member(node, "direction")) light.direction = readDirection(*direction);
    if (auto range = member(node, "range")) light.range = readNumber(*range, above(0));
    readSpotAngles(node, light);
    if (auto color = member(node, "color")) light.color = readVec3(*color, atLeast(0));
    if (auto intensity = member(node, "intensity")) light.intensity = readNumber(*intensity, atLeast(0));
    if (auto mode = member(node, "mode")) light.mode = readChoice(*mode, kLightModes);
    if (auto shadows = member(node, "shadows")) light.shadows = readBool(*shadows);
    if (auto strength = member(node, "shadow_strength")) light.shadowStrength = readNumber(*strength, closed(0, 1));
    if (auto falloff = member(node, "bake_falloff")) light.bakeFalloff = readChoice(*falloff, kBakeFalloffs);
    if (auto cookie = member(node, "cookie")) light.cookie = readCookie(*cookie, light);
    readShadowMap(node, light);
    return light;
  }

  // SPEC 2 and 3.9: `shadows` on a realtime light is a shadow map, shaped by
  // `shadow_map` (defaults without it). On a mixed or baked light `shadows`
  // keeps its baked meaning and a `shadow_map` is an error; on a realtime
  // light without `shadows` the map is checked but unused, so a scene can
  // switch shadows off without deleting it.
  void readShadowMap(const Node& lightNode, Light& light) const {
    const auto node = member(lightNode, "shadow_map");
    if (node && light.mode != LightMode::Realtime) {
      fail(*node, "a shadow_map needs a realtime light (SPEC 2; a " +
                      std::string(wordOf(kLightModes, light.mode)) +
                      " light's shadows are baked into the shadow mask or lightmap)");
    }
    if (light.mode != LightMode::Realtime || (!light.shadows && !node)) return;
    const Node& where = node ? *node : *member(lightNode, "shadows");
    ShadowMapSpec map;
    const bool directional = light.type == LightType::Directional;
    if (node) {
      expectObject(*node);
      const std::string type(wordOf(kLightTypes, light.type));
      const OtherVariants others{kShadowMapKeys, "a " + type + " light's shadow_map"};
      if (directional) checkKeys(*node, kDirectionalShadowMapKeys, &others);
      else checkKeys(*node, kLocalShadowMapKeys, &others);
      if (auto resolution = member(*node, "resolution")) {
        map.resolution = readInt(*resolution, kMinShadowMapResolution, kMaxShadowMapResolution);
        if ((map.resolution & (map.resolution - 1)) != 0)
          fail(*resolution, "expected a power of two in [16, 4096], got " + std::to_string(map.resolution));
      }
      if (auto filter = member(*node, "filter")) {
        map.filter = readChoice(*filter, kShadowFilters);
        if (map.filter == ShadowFilter::Tent3x3 && light.type == LightType::Point)
          fail(*filter, "tent3x3 is not available on a point light's cube map (SPEC 2); use hard or bilinear");
      }
      if (auto bias = member(*node, "depth_bias")) map.depthBias = readNumber(*bias, atLeast(0));
      if (auto bias = member(*node, "normal_bias")) map.normalBias = readNumber(*bias, atLeast(0));
      if (auto nearNode = member(*node, "near")) map.nearPlane = readNumber(*nearNode, {0, true, light.range, true});
      if (auto center = member(*node, "center")) map.center = readVec3(*center);
      if (auto extent = member(*node, "extent")) map.extent = readNumber(*extent, above(0));
    }
    if (!directional && !(map.nearPlane < light.range)) {
      fail(where, "the shadow map's near plane " + formatJsonNumber(map.nearPlane) + " must lie in (0, range = " +
                      formatJsonNumber(light.range) + ") (SPEC 2)");
    }
    if (light.type == LightType::Spot && light.spotAngleDeg > kWidestShadowedSpotDeg) {
      fail(where, "a shadowed spot needs spot_angle_deg <= 170 (SPEC 2), this spot has " +
                      formatJsonNumber(light.spotAngleDeg));
    }
    if (light.shadows) light.shadowMap = map;
  }

  LightType readLightType(const Node& node) const {
    if (node.value.is_string() && node.value.get<std::string>() == "area") {
      fail(node, "area lights are not part of this model yet (baked-only area lights, SPEC 2)");
    }
    return readChoice(node, kLightTypes);
  }

  // SPEC 2: the direction the light travels, stored normalised.
  Vec3 readDirection(const Node& node) const {
    const auto unit = unitVector(readVec3(node));
    if (!unit) fail(node, "direction must not be the zero vector");
    return *unit;
  }

  // SPEC 2 and 3.10: the cookie's keys by light type, its files read now, so
  // a bad file is a scene error (exit 2) naming the JSON path and the file.
  Cookie readCookie(const Node& node, const Light& light) const {
    expectObject(node);
    if (light.mode != LightMode::Realtime) {
      fail(node, "a cookie needs a realtime light (SPEC 2); this light is " +
                     std::string(wordOf(kLightModes, light.mode)));
    }
    const std::string type(wordOf(kLightTypes, light.type));
    const OtherVariants others{kCookieKeys, "a " + type + " light's cookie"};
    Cookie cookie;
    switch (light.type) {
      case LightType::Directional: {
        checkKeys(node, kDirectionalCookieKeys, &others);
        requireMember(node, "image");
        requireMember(node, "size");
        readCookieImage(*member(node, "image"), cookie);
        std::tie(cookie.sizeX, cookie.sizeY) = readPositivePair(*member(node, "size"), "[w, h]");
        break;
      }
      case LightType::Spot:
        checkKeys(node, kSpotCookieKeys, &others);
        requireMember(node, "image");
        if (light.spotAngleDeg > kWidestCookieSpotDeg)
          fail(node, "a spot cookie needs spot_angle_deg <= 170 (SPEC 2), this spot has " +
                         formatJsonNumber(light.spotAngleDeg));
        readCookieImage(*member(node, "image"), cookie);
        break;
      case LightType::Point: {
        checkKeys(node, kPointCookieKeys, &others);
        requireMember(node, "cube");
        const Node cube = *member(node, "cube");
        if (!cube.value.is_array() || cube.value.size() != kCubeFaces)
          fail(cube, "expected the six faces [+X, -X, +Y, -Y, +Z, -Z], got " + describeJsonTypeAndLength(cube.value));
        for (std::size_t f = 0; f < kCubeFaces; ++f) {
          const Node face = cube.element(f);
          readCookieImage(face, cookie);
          const CookieImage& image = *cookie.images.back();
          const CookieImage& first = *cookie.images.front();
          if (image.width != image.height)
            fail(face, "cube face '" + cookie.files.back() + "' is " + std::to_string(image.width) + "x" +
                           std::to_string(image.height) + "; cube faces must be square");
          if (image.width != first.width)
            fail(face, "cube face '" + cookie.files.back() + "' is " + std::to_string(image.width) +
                           " texels wide, face 0 is " + std::to_string(first.width) + "; the faces must be equal");
        }
        break;
      }
    }
    return cookie;
  }

  void readCookieImage(const Node& node, Cookie& cookie) const {
    const std::string name = readString(node);
    const std::filesystem::path resolved = std::filesystem::path(file_).parent_path() / name;
    imaging::Image read;
    try {
      read = imaging::readDataChannel(resolved.string());
    } catch (const imaging::ImageFileError& error) {
      fail(node, "cannot read the cookie image '" + resolved.string() + "' (PNG or EXR): " + error.what());
    }
    auto image = std::make_shared<CookieImage>();
    image->width = read.width;
    image->height = read.height;
    image->texels = std::move(read.pixels);
    cookie.files.push_back(resolved.string());
    cookie.images.push_back(std::move(image));
  }

  // SPEC 2: the outer angle in (0, 180]; the inner one in [0, outer], optional (3.4).
  void readSpotAngles(const Node& node, Light& light) const {
    if (auto outer = member(node, "spot_angle_deg")) light.spotAngleDeg = readNumber(*outer, {0, true, 180, false});
    if (auto inner = member(node, "inner_spot_angle_deg")) {
      light.innerSpotAngleDeg = readNumber(*inner, closed(0, light.spotAngleDeg));
    }
  }

  Frames readFrames(const Node& node, const Camera& camera) const {
    expectObject(node);
    checkKeys(node, kFramesKeys);
    Frames frames;
    const auto count = member(node, "count");
    if (count) frames.count = readInt(*count, 1, kMaxFrames);
    const auto path = member(node, "camera_path");
    if (!path) return frames;
    if (!path->value.is_array()) fail(*path, "expected an array of keyframes, got " + describeJsonType(path->value));
    if (path->value.size() == 1) {
      fail(*path, "expected no keyframes (a still camera) or at least 2, got 1");
    }
    for (std::size_t k = 0; k < path->value.size(); ++k) {
      frames.cameraPath.push_back(readKeyframe(path->element(k), camera));
    }
    // SPEC 2 puts frame f at t = f / (count - 1), undefined for one frame.
    if (!frames.cameraPath.empty() && frames.count < 2) {
      fail(count ? *count : *path, "a camera path needs frames.count >= 2, got " + std::to_string(frames.count) +
                                       (count ? "" : " (the default)"));
    }
    return frames;
  }

  CameraKeyframe readKeyframe(const Node& node, const Camera& camera) const {
    expectObject(node);
    checkKeys(node, kKeyframeKeys);
    for (const std::string_view key : kKeyframeKeys) requireMember(node, key);
    const Node target = *member(node, "target");
    CameraKeyframe keyframe{readVec3(*member(node, "position")), readVec3(target)};
    // Keyframes replace the camera's position and target, so each must make a valid lookAt.
    if (auto problem = lookAtProblem(keyframe.position, keyframe.target, camera.up)) {
      fail(target, describe(*problem, camera.up));
    }
    return keyframe;
  }

  Expectation readExpectation(const Node& node) const {
    expectObject(node);
    checkKeys(node, kExpectKeys);
    Expectation expect;
    if (auto scale = member(node, "tolerance_scale")) expect.toleranceScale = readNumber(*scale, above(0));
    if (auto pixels = member(node, "max_failing_pixels")) {
      expect.maxFailingPixels = readInteger(*pixels, 0, kMaxExactInteger);
    }
    if (auto expectFail = member(node, "expect_fail")) expect.expectFail = readBool(*expectFail);
    if (auto against = member(node, "against")) expect.against = readChoice(*against, kCompareAgainst);
    return expect;
  }

  std::string_view text_;
  std::string file_;
};

}  // namespace

Scene loadSceneText(std::string_view text, const std::string& sourceName) {
  Json document;
  try {
    document = readJsonInput(text, "a scene");
  } catch (const JsonInputError& error) {
    throwSceneError(sourceName, error.pointer(), error.where(), error.message());
  }
  Scene scene = SceneReader(text, sourceName).readScene(document);
  scene.sourcePath = sourceName;
  return scene;
}

Scene loadSceneFile(const std::string& path) {
  if (isGltfPath(path)) {
    Scene scene = bareGltfScene(path);
    scene.sourcePath = path;
    return scene;
  }
  std::error_code ignored;
  if (std::filesystem::is_directory(path, ignored)) {
    throwSceneError(path, "", {}, "cannot read the scene file: it is a directory");
  }
  errno = 0;
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    const std::string reason = errno != 0 ? std::string(" (") + std::strerror(errno) + ")" : "";
    throwSceneError(path, "", {}, "cannot open the scene file" + reason);
  }
  std::ostringstream content;
  content << in.rdbuf();
  if (in.bad()) throwSceneError(path, "", {}, "cannot read the scene file");
  return loadSceneText(content.str(), path);
}

}  // namespace scene_input
