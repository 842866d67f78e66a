#include "scene_input/gltf_json_checks.h"

#include "scene_input/gltf_import.h"
#include "scene_input/json_cursor.h"
#include "scene_input/json_describe.h"
#include "scene_input/json_input.h"

#include <cmath>
#include <map>
#include <numbers>
#include <set>
#include <string_view>

namespace scene_input {

using namespace lighting;  // the model this folder reads scenes into
namespace {

using Json = nlohmann::json;
using Cursor = JsonCursor<Json>;

// The one extension the model reads (SPEC 2.1).
constexpr std::string_view kLightsExtension = "KHR_lights_punctual";

std::string numberText(const Json& value) { return value.dump(); }

class ShapeChecker {
 public:
  ShapeChecker(const Json& root, const std::string& file, std::vector<std::string>& warnings)
      : root_(Cursor::root(root)), file_(file), warnings_(warnings) {}

  void check() {
    if (!root_.value.is_object()) fail(root_, "expected a JSON object, got " + describeJsonTypeAndLength(root_.value));
    checkAsset();
    checkExtensionLists();
    sizes_ = {{"scenes", arraySize("scenes")},       {"nodes", arraySize("nodes")},
              {"meshes", arraySize("meshes")},       {"accessors", arraySize("accessors")},
              {"bufferViews", arraySize("bufferViews")}, {"buffers", arraySize("buffers")},
              {"materials", arraySize("materials")}, {"cameras", arraySize("cameras")}};
    lightCount_ = checkLightsList();
    if (const auto scene = root_.member("scene")) index(*scene, "scenes");
    forEach("scenes", [&](const Cursor& c) { checkScene(c); });
    forEach("nodes", [&](const Cursor& c) { checkNode(c); });
    forEach("meshes", [&](const Cursor& c) { checkMesh(c); });
    forEach("accessors", [&](const Cursor& c) { checkAccessor(c); });
    forEach("bufferViews", [&](const Cursor& c) { checkBufferView(c); });
    forEach("buffers", [&](const Cursor& c) { checkBuffer(c); });
    forEach("materials", [&](const Cursor& c) { checkMaterial(c); });
    forEach("cameras", [&](const Cursor& c) { checkCamera(c); });
    for (const auto& [what, where] : ignored_) warn(where.first, what + where.second);
  }

 private:
  [[noreturn]] void fail(const std::string& pointer, const std::string& message) const {
    throw GltfError(file_, pointer, message);
  }
  [[noreturn]] void fail(const Cursor& at, const std::string& message) const { fail(at.pointer, message); }
  [[noreturn]] void failMissing(const Cursor& object, const std::string& key) const {
    fail(object.pointerTo(key), "missing required key '" + key + "'");
  }
  void warn(const std::string& pointer, const std::string& message) const {
    warnings_.push_back(file_ + ": " + (pointer.empty() ? "" : pointer + ": ") + message);
  }
  void warn(const Cursor& at, const std::string& message) const { warn(at.pointer, message); }
  // Content outside the model: one warning per kind, at its first place,
  // with how many more there are (an engine has dozens of textures).
  void noteIgnored(const std::string& what, const Cursor& at) {
    auto [it, inserted] = ignored_.try_emplace(what, at.pointer, std::string());
    ++ignoredCount_[what];
    if (!inserted) it->second.second = " (and " + std::to_string(ignoredCount_[what] - 1) + " more)";
  }

  // The member `key` of `object`, which must be there.
  Cursor required(const Cursor& object, const std::string& key) const {
    const auto found = object.member(key);
    if (!found) failMissing(object, key);
    return *found;
  }

  void expectObject(const Cursor& c) const {
    if (auto problem = kindProblem(c.value, JsonKind::Object)) fail(c, *problem);
  }
  void expectArray(const Cursor& c) const {
    if (auto problem = kindProblem(c.value, JsonKind::Array)) fail(c, *problem);
  }

  std::size_t arraySize(std::string_view key) const {
    const auto list = root_.member(key);
    if (!list) return 0;
    expectArray(*list);
    return list->value.size();
  }

  template <typename F>
  void forEach(std::string_view key, F&& checkOne) {
    const auto list = root_.member(key);
    if (!list) return;
    for (std::size_t i = 0; i < list->value.size(); ++i) {
      const Cursor element = list->element(i);
      expectObject(element);
      checkName(element);
      checkOne(element);
    }
  }

  static bool isInteger(const Json& value) {
    if (value.is_number_integer()) return true;
    if (!value.is_number_float()) return false;
    const double v = value.get<double>();
    return std::isfinite(v) && std::trunc(v) == v;
  }

  // An integer in [min, max].
  long long integer(const Cursor& c, long long min, long long max) const {
    if (auto problem = integerProblem(c.value, min, max)) fail(c, *problem);
    return static_cast<long long>(c.value.get<double>());
  }

  // An index into the top-level array `list`.
  long long index(const Cursor& c, const std::string& list) const {
    const std::size_t count = list == "lights" ? lightCount_ : sizes_.at(list);
    if (!isInteger(c.value)) fail(c, "expected an index into " + list + ", got " + describeJsonTypeAndLength(c.value));
    const double v = c.value.get<double>();
    if (v < 0 || v >= double(count)) {
      fail(c, list + " index " + numberText(c.value) + " is out of range (the file has " + std::to_string(count) + " " +
                  list + ")");
    }
    return c.value.get<long long>();
  }

  // Every element of the array `c`, an index into `list`.
  void indices(const Cursor& c, const std::string& list) const {
    expectArray(c);
    for (std::size_t i = 0; i < c.value.size(); ++i) index(c.element(i), list);
  }

  double number(const Cursor& c, double min, double max, bool minOpen = false) const {
    if (auto problem = numberProblem(c.value, NumberBounds{min, minOpen, max, false})) fail(c, *problem);
    return c.value.get<double>();
  }

  void numbers(const Cursor& c, std::size_t count, double min, double max) const {
    if (!c.value.is_array() || c.value.size() != count) {
      fail(c, "expected an array of " + std::to_string(count) + " numbers, got " + describeJsonTypeAndLength(c.value));
    }
    for (std::size_t i = 0; i < count; ++i) number(c.element(i), min, max);
  }

  void boolean(const Cursor& c) const {
    if (auto problem = kindProblem(c.value, JsonKind::Boolean)) fail(c, *problem);
  }

  // Names are never read by the model, except as object names; a wrong type
  // is a warning.
  void checkName(const Cursor& object) const {
    if (const auto name = object.member("name"); name && !name->value.is_string()) {
      warn(*name, "expected a string, got " + describeJsonTypeAndLength(name->value) + "; ignored");
    }
  }

  static constexpr double kInf = INFINITY;

  // --- the document ---------------------------------------------------------

  void checkAsset() const {
    const Cursor asset = required(root_, "asset");
    expectObject(asset);
    const auto version = asset.member("version");
    if (!version || !version->value.is_string()) fail(asset.pointerTo("version"), "expected the glTF version as a string");
    const std::string text = version->value.get<std::string>();
    if (text.rfind("2.", 0) != 0) fail(*version, "expected glTF version 2.x, got '" + text + "'");
  }

  void checkExtensionLists() {
    for (const char* key : {"extensionsUsed", "extensionsRequired"}) {
      const auto list = root_.member(key);
      if (!list) continue;
      expectArray(*list);
      for (std::size_t i = 0; i < list->value.size(); ++i) {
        const Cursor at = list->element(i);
        if (!at.value.is_string()) fail(at, "expected an extension name, got " + describeJsonTypeAndLength(at.value));
        const std::string name = at.value.get<std::string>();
        if (name == kLightsExtension) continue;
        if (std::string_view(key) == "extensionsRequired") {
          fail(at, "the file requires the extension " + name + ", which lightcts does not read (it reads " +
                       std::string(kLightsExtension) + " only)");
        }
        warn(at, "extension " + name + " is not part of the model; ignored");
      }
    }
  }

  std::size_t checkLightsList() const {
    const auto extensions = root_.member("extensions");
    if (!extensions) return 0;
    expectObject(*extensions);
    const auto lights = extensions->member(kLightsExtension);
    if (!lights) return 0;
    expectObject(*lights);
    const auto list = lights->member("lights");
    if (!list) return 0;
    expectArray(*list);
    for (std::size_t i = 0; i < list->value.size(); ++i) checkLight(list->element(i));
    return list->value.size();
  }

  void checkLight(const Cursor& light) const {
    expectObject(light);
    checkName(light);
    const Cursor type = required(light, "type");
    const std::string typeName = type.value.is_string() ? type.value.get<std::string>() : "";
    if (typeName != "directional" && typeName != "point" && typeName != "spot") {
      fail(type, "expected directional, point or spot, got " +
                     (type.value.is_string() ? "'" + typeName + "'" : describeJsonTypeAndLength(type.value)));
    }
    if (const auto color = light.member("color")) numbers(*color, 3, 0, kInf);
    if (const auto intensity = light.member("intensity")) number(*intensity, 0, kInf);
    if (const auto range = light.member("range")) number(*range, 0, kInf, true);
    if (typeName != "spot") return;
    const auto spot = light.member("spot");
    if (!spot) fail(light.pointerTo("spot"), "a spot light needs its 'spot' object");
    expectObject(*spot);
    double outer = std::numbers::pi / 4, inner = 0;
    if (const auto o = spot->member("outerConeAngle")) outer = number(*o, 0, std::numbers::pi / 2, true);
    if (const auto i = spot->member("innerConeAngle")) inner = number(*i, 0, kInf);
    if (inner > outer) {
      fail(spot->pointerTo("innerConeAngle"),
           "innerConeAngle " + Json(inner).dump() + " is wider than outerConeAngle " + Json(outer).dump());
    }
  }

  void checkScene(const Cursor& scene) const {
    if (const auto nodes = scene.member("nodes")) indices(*nodes, "nodes");
  }

  void checkNode(const Cursor& node) {
    if (const auto children = node.member("children")) indices(*children, "nodes");
    if (const auto mesh = node.member("mesh")) index(*mesh, "meshes");
    if (const auto camera = node.member("camera")) index(*camera, "cameras");
    const auto matrix = node.member("matrix");
    if (matrix) numbers(*matrix, 16, -kInf, kInf);
    for (const auto& [key, count] : {std::pair{"translation", 3}, {"rotation", 4}, {"scale", 3}}) {
      const auto value = node.member(key);
      if (!value) continue;
      numbers(*value, std::size_t(count), -kInf, kInf);
      if (matrix) fail(*value, std::string("a node may have a matrix or ") + key + ", not both");
    }
    if (const auto skin = node.member("skin"))
      noteIgnored("skins are not part of the model; the mesh is drawn in its bind pose", *skin);
    if (const auto weights = node.member("weights"))
      noteIgnored("morph weights are not part of the model; ignored", *weights);
    const auto extensions = node.member("extensions");
    if (!extensions) return;
    expectObject(*extensions);
    const auto lights = extensions->member(kLightsExtension);
    if (!lights) return;
    expectObject(*lights);
    index(required(*lights, "light"), "lights");
  }

  void checkMesh(const Cursor& mesh) {
    const Cursor primitives = required(mesh, "primitives");
    expectArray(primitives);
    if (primitives.value.empty()) fail(primitives, "a mesh needs at least one primitive");
    for (std::size_t i = 0; i < primitives.value.size(); ++i) {
      const Cursor primitive = primitives.element(i);
      expectObject(primitive);
      const Cursor attributes = required(primitive, "attributes");
      expectObject(attributes);
      for (const auto& item : attributes.value.items()) index(attributes.item(item.key(), item.value()), "accessors");
      if (const auto indices = primitive.member("indices")) index(*indices, "accessors");
      if (const auto mode = primitive.member("mode")) integer(*mode, 0, 6);
      if (const auto material = primitive.member("material")) index(*material, "materials");
      if (const auto targets = primitive.member("targets"))
        noteIgnored("morph targets are not part of the model; ignored", *targets);
    }
  }

  void checkAccessor(const Cursor& accessor) const {
    if (const auto view = accessor.member("bufferView")) index(*view, "bufferViews");
    if (const auto offset = accessor.member("byteOffset")) integer(*offset, 0, kMaxBytes);
    const Cursor componentType = required(accessor, "componentType");
    const long long component = integer(componentType, 5120, 5126);
    if (component == 5124) fail(componentType, "5124 (signed int) is not a glTF 2.0 component type");
    integer(required(accessor, "count"), 1, kMaxBytes);
    const auto type = accessor.member("type");
    static const std::set<std::string> kTypes{"SCALAR", "VEC2", "VEC3", "VEC4", "MAT2", "MAT3", "MAT4"};
    if (!type || !type->value.is_string() || !kTypes.count(type->value.get<std::string>())) {
      fail(accessor.pointerTo("type"), "expected one of SCALAR, VEC2, VEC3, VEC4, MAT2, MAT3, MAT4, got " +
                                           (type ? type->value.dump() : std::string("nothing")));
    }
    if (const auto normalized = accessor.member("normalized")) boolean(*normalized);
    if (const auto sparse = accessor.member("sparse")) expectObject(*sparse);
  }

  void checkBufferView(const Cursor& view) const {
    index(required(view, "buffer"), "buffers");
    if (const auto offset = view.member("byteOffset")) integer(*offset, 0, kMaxBytes);
    integer(required(view, "byteLength"), 1, kMaxBytes);
    if (const auto stride = view.member("byteStride")) {
      const long long s = integer(*stride, 4, 252);
      if (s % 4 != 0) fail(*stride, "expected a multiple of 4, got " + std::to_string(s));
    }
  }

  void checkBuffer(const Cursor& buffer) const {
    integer(required(buffer, "byteLength"), 1, kMaxBytes);
    if (const auto uri = buffer.member("uri"); uri && !uri->value.is_string())
      fail(*uri, "expected a string, got " + describeJsonTypeAndLength(uri->value));
  }

  void checkMaterial(const Cursor& material) {
    if (const auto pbr = material.member("pbrMetallicRoughness")) {
      expectObject(*pbr);
      if (const auto color = pbr->member("baseColorFactor")) numbers(*color, 4, 0, 1);
      if (const auto metallic = pbr->member("metallicFactor")) number(*metallic, 0, 1);
      if (const auto roughness = pbr->member("roughnessFactor")) number(*roughness, 0, 1);
      for (const char* texture : {"baseColorTexture", "metallicRoughnessTexture"})
        if (const auto info = pbr->member(texture)) checkTextureInfo(*info);
    }
    if (const auto sided = material.member("doubleSided")) boolean(*sided);
    for (const char* texture : {"normalTexture", "occlusionTexture", "emissiveTexture"})
      if (const auto info = material.member(texture)) checkTextureInfo(*info);
    if (const auto emissive = material.member("emissiveFactor")) {
      numbers(*emissive, 3, 0, 1);
      if (emissive->value[0] != 0 || emissive->value[1] != 0 || emissive->value[2] != 0)
        noteIgnored("emission is not part of the model; ignored", *emissive);
    }
    if (const auto alpha = material.member("alphaMode"); alpha && alpha->value != "OPAQUE")
      noteIgnored("alpha modes are not part of the model; drawn opaque", *alpha);
    if (const auto extensions = material.member("extensions"))
      if (extensions->value.is_object() && !extensions->value.empty())
        noteIgnored("material extensions are not part of the model; ignored", *extensions);
  }

  // Textures are not part of the model: a reference to one is ignored, and
  // a malformed reference is named, so the author learns of it.
  void checkTextureInfo(const Cursor& info) {
    noteIgnored("textures are not part of the model; ignored", info);
    if (!info.value.is_object()) {
      warn(info, "expected a texture reference object, got " + describeJsonTypeAndLength(info.value) + "; ignored");
      return;
    }
    const auto index = info.member("index");
    if (!index) warn(info, "a texture reference without 'index'; ignored");
    else if (!isInteger(index->value) || index->value.get<double>() < 0)
      warn(*index, "expected a texture index >= 0, got " + index->value.dump() + "; ignored");
    if (const auto texCoord = info.member("texCoord");
        texCoord && (!isInteger(texCoord->value) || texCoord->value.get<double>() < 0))
      warn(*texCoord, "expected an integer >= 0, got " + texCoord->value.dump() + "; ignored");
    for (const char* key : {"scale", "strength"})
      if (const auto value = info.member(key); value && !value->value.is_number())
        warn(*value, "expected a number, got " + describeJsonTypeAndLength(value->value) + "; ignored");
    if (const auto extensions = info.member("extensions")) {
      if (!extensions->value.is_object()) {
        warn(*extensions, "expected an object, got " + describeJsonTypeAndLength(extensions->value) + "; ignored");
      } else {
        for (const auto& item : extensions->value.items())
          if (!item.value().is_object())
            warn(extensions->item(item.key(), item.value()),
                 "expected an object, got " + describeJsonTypeAndLength(item.value()) + "; ignored");
      }
    }
  }

  void checkCamera(const Cursor& camera) const {
    const auto type = camera.member("type");
    const std::string name = type && type->value.is_string() ? type->value.get<std::string>() : "";
    if (name != "perspective" && name != "orthographic")
      fail(camera.pointerTo("type"),
           "expected perspective or orthographic, got " + (type ? type->value.dump() : std::string("nothing")));
    const Cursor body = required(camera, name);
    expectObject(body);
    auto requiredNumber = [&](const char* key, double min, double max, bool minOpen) {
      return number(required(body, key), min, max, minOpen);
    };
    if (name == "perspective") {
      requiredNumber("yfov", 0, std::numbers::pi, true);
      const double znear = requiredNumber("znear", 0, kInf, true);
      if (const auto zfar = body.member("zfar")) number(*zfar, znear, kInf, true);
      if (const auto aspect = body.member("aspectRatio")) number(*aspect, 0, kInf, true);
    } else {
      requiredNumber("xmag", -kInf, kInf, false);
      const double ymag = requiredNumber("ymag", -kInf, kInf, false);
      if (ymag == 0) fail(body.pointerTo("ymag"), "ymag must not be 0");
      const double znear = requiredNumber("znear", 0, kInf, false);
      requiredNumber("zfar", znear, kInf, true);
    }
  }

  // Byte counts and offsets beyond this are not a file lightcts can hold.
  static constexpr long long kMaxBytes = 1LL << 40;

  const Cursor root_;
  const std::string& file_;
  std::vector<std::string>& warnings_;
  std::map<std::string, std::size_t> sizes_;
  std::size_t lightCount_ = 0;
  std::map<std::string, std::pair<std::string, std::string>> ignored_;  // what -> (first pointer, "(and N more)")
  std::map<std::string, std::size_t> ignoredCount_;
};

}  // namespace

void checkGltfJson(const Json& document, const std::string& file, std::vector<std::string>& warnings) {
  ShapeChecker(document, file, warnings).check();
}

}  // namespace scene_input
