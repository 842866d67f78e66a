#include "scene_input/gltf_json_checks.h"

#include "scene_input/gltf_import.h"
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

// The one extension the model reads (SPEC 2.1).
constexpr std::string_view kLightsExtension = "KHR_lights_punctual";

std::string numberText(const Json& value) { return value.dump(); }

class ShapeChecker {
 public:
  ShapeChecker(const Json& root, const std::string& file, std::vector<std::string>& warnings)
      : root_(root), file_(file), warnings_(warnings) {}

  void check() {
    if (!root_.is_object()) fail("", "expected a JSON object, got " + describeJsonTypeAndLength(root_));
    checkAsset();
    checkExtensionLists();
    sizes_ = {{"scenes", arraySize("scenes")},       {"nodes", arraySize("nodes")},
              {"meshes", arraySize("meshes")},       {"accessors", arraySize("accessors")},
              {"bufferViews", arraySize("bufferViews")}, {"buffers", arraySize("buffers")},
              {"materials", arraySize("materials")}, {"cameras", arraySize("cameras")}};
    lightCount_ = checkLightsList();
    if (const Json* scene = member(root_, "scene")) index(*scene, "/scene", "scenes");
    forEach("scenes", [&](const Json& s, const std::string& p) { checkScene(s, p); });
    forEach("nodes", [&](const Json& n, const std::string& p) { checkNode(n, p); });
    forEach("meshes", [&](const Json& m, const std::string& p) { checkMesh(m, p); });
    forEach("accessors", [&](const Json& a, const std::string& p) { checkAccessor(a, p); });
    forEach("bufferViews", [&](const Json& v, const std::string& p) { checkBufferView(v, p); });
    forEach("buffers", [&](const Json& b, const std::string& p) { checkBuffer(b, p); });
    forEach("materials", [&](const Json& m, const std::string& p) { checkMaterial(m, p); });
    forEach("cameras", [&](const Json& c, const std::string& p) { checkCamera(c, p); });
    for (const auto& [what, where] : ignored_) warn(where.first, what + where.second);
  }

 private:
  [[noreturn]] void fail(const std::string& pointer, const std::string& message) const {
    throw GltfError(file_, pointer, message);
  }
  void warn(const std::string& pointer, const std::string& message) const {
    warnings_.push_back(file_ + ": " + (pointer.empty() ? "" : pointer + ": ") + message);
  }
  // Content outside the model: one warning per kind, at its first place,
  // with how many more there are (an engine has dozens of textures).
  void noteIgnored(const std::string& what, const std::string& pointer) {
    auto [it, inserted] = ignored_.try_emplace(what, pointer, std::string());
    ++ignoredCount_[what];
    if (!inserted) it->second.second = " (and " + std::to_string(ignoredCount_[what] - 1) + " more)";
  }

  static const Json* member(const Json& object, std::string_view key) {
    const auto found = object.find(key);
    return found == object.end() ? nullptr : &*found;
  }

  void expectObject(const Json& value, const std::string& pointer) const {
    if (auto problem = kindProblem(value, JsonKind::Object)) fail(pointer, *problem);
  }
  void expectArray(const Json& value, const std::string& pointer) const {
    if (auto problem = kindProblem(value, JsonKind::Array)) fail(pointer, *problem);
  }

  std::size_t arraySize(std::string_view key) const {
    const Json* list = member(root_, key);
    if (!list) return 0;
    expectArray(*list, "/" + std::string(key));
    return list->size();
  }

  template <typename F>
  void forEach(std::string_view key, F&& checkOne) {
    const Json* list = member(root_, key);
    if (!list) return;
    for (std::size_t i = 0; i < list->size(); ++i) {
      const std::string pointer = "/" + std::string(key) + "/" + std::to_string(i);
      expectObject((*list)[i], pointer);
      checkName((*list)[i], pointer);
      checkOne((*list)[i], pointer);
    }
  }

  static bool isInteger(const Json& value) {
    if (value.is_number_integer()) return true;
    if (!value.is_number_float()) return false;
    const double v = value.get<double>();
    return std::isfinite(v) && std::trunc(v) == v;
  }

  // An integer in [min, max].
  long long integer(const Json& value, const std::string& pointer, long long min, long long max) const {
    if (auto problem = integerProblem(value, min, max)) fail(pointer, *problem);
    return static_cast<long long>(value.get<double>());
  }

  // An index into the top-level array `list`.
  long long index(const Json& value, const std::string& pointer, const std::string& list) const {
    const std::size_t count = list == "lights" ? lightCount_ : sizes_.at(list);
    if (!isInteger(value)) fail(pointer, "expected an index into " + list + ", got " + describeJsonTypeAndLength(value));
    const double v = value.get<double>();
    if (v < 0 || v >= double(count)) {
      fail(pointer, list + " index " + numberText(value) + " is out of range (the file has " + std::to_string(count) +
                        " " + list + ")");
    }
    return value.get<long long>();
  }

  double number(const Json& value, const std::string& pointer, double min, double max, bool minOpen = false) const {
    if (auto problem = numberProblem(value, NumberBounds{min, minOpen, max, false})) fail(pointer, *problem);
    return value.get<double>();
  }

  void numbers(const Json& value, const std::string& pointer, std::size_t count, double min, double max) const {
    if (!value.is_array() || value.size() != count) {
      fail(pointer, "expected an array of " + std::to_string(count) + " numbers, got " + describeJsonTypeAndLength(value));
    }
    for (std::size_t i = 0; i < count; ++i) number(value[i], pointer + "/" + std::to_string(i), min, max);
  }

  void boolean(const Json& value, const std::string& pointer) const {
    if (auto problem = kindProblem(value, JsonKind::Boolean)) fail(pointer, *problem);
  }

  // Names are never read by the model, except as object names; a wrong type
  // is a warning.
  void checkName(const Json& object, const std::string& pointer) const {
    if (const Json* name = member(object, "name"); name && !name->is_string()) {
      warn(pointer + "/name", "expected a string, got " + describeJsonTypeAndLength(*name) + "; ignored");
    }
  }

  static constexpr double kInf = INFINITY;

  // --- the document ---------------------------------------------------------

  void checkAsset() const {
    const Json* asset = member(root_, "asset");
    if (!asset) fail("/asset", "missing required key 'asset'");
    expectObject(*asset, "/asset");
    const Json* version = member(*asset, "version");
    if (!version || !version->is_string()) fail("/asset/version", "expected the glTF version as a string");
    const std::string text = version->get<std::string>();
    if (text.rfind("2.", 0) != 0) fail("/asset/version", "expected glTF version 2.x, got '" + text + "'");
  }

  void checkExtensionLists() {
    for (const char* key : {"extensionsUsed", "extensionsRequired"}) {
      const Json* list = member(root_, key);
      if (!list) continue;
      const std::string pointer = std::string("/") + key;
      expectArray(*list, pointer);
      for (std::size_t i = 0; i < list->size(); ++i) {
        const std::string at = pointer + "/" + std::to_string(i);
        if (!(*list)[i].is_string()) fail(at, "expected an extension name, got " + describeJsonTypeAndLength((*list)[i]));
        const std::string name = (*list)[i].get<std::string>();
        if (name == kLightsExtension) continue;
        if (std::string_view(key) == "extensionsRequired") {
          fail(at, "the file requires the extension " + name +
                       ", which lightcts does not read (it reads " + std::string(kLightsExtension) + " only)");
        }
        warn(at, "extension " + name + " is not part of the model; ignored");
      }
    }
  }

  std::size_t checkLightsList() const {
    const Json* extensions = member(root_, "extensions");
    if (!extensions) return 0;
    expectObject(*extensions, "/extensions");
    const Json* lights = member(*extensions, kLightsExtension);
    if (!lights) return 0;
    const std::string base = "/extensions/" + std::string(kLightsExtension);
    expectObject(*lights, base);
    const Json* list = member(*lights, "lights");
    if (!list) return 0;
    expectArray(*list, base + "/lights");
    for (std::size_t i = 0; i < list->size(); ++i) checkLight((*list)[i], base + "/lights/" + std::to_string(i));
    return list->size();
  }

  void checkLight(const Json& light, const std::string& pointer) const {
    expectObject(light, pointer);
    checkName(light, pointer);
    const Json* type = member(light, "type");
    if (!type) fail(pointer + "/type", "missing required key 'type'");
    const std::string typeName = type->is_string() ? type->get<std::string>() : "";
    if (typeName != "directional" && typeName != "point" && typeName != "spot") {
      fail(pointer + "/type", "expected directional, point or spot, got " +
                                  (type->is_string() ? "'" + typeName + "'" : describeJsonTypeAndLength(*type)));
    }
    if (const Json* color = member(light, "color")) numbers(*color, pointer + "/color", 3, 0, kInf);
    if (const Json* intensity = member(light, "intensity")) number(*intensity, pointer + "/intensity", 0, kInf);
    if (const Json* range = member(light, "range")) number(*range, pointer + "/range", 0, kInf, true);
    const Json* spot = member(light, "spot");
    if (typeName != "spot") return;
    if (!spot) fail(pointer + "/spot", "a spot light needs its 'spot' object");
    expectObject(*spot, pointer + "/spot");
    double outer = std::numbers::pi / 4, inner = 0;
    if (const Json* o = member(*spot, "outerConeAngle"))
      outer = number(*o, pointer + "/spot/outerConeAngle", 0, std::numbers::pi / 2, true);
    if (const Json* i = member(*spot, "innerConeAngle")) inner = number(*i, pointer + "/spot/innerConeAngle", 0, kInf);
    if (inner > outer) {
      fail(pointer + "/spot/innerConeAngle", "innerConeAngle " + Json(inner).dump() +
                                                 " is wider than outerConeAngle " + Json(outer).dump());
    }
  }

  void checkScene(const Json& scene, const std::string& pointer) const {
    const Json* nodes = member(scene, "nodes");
    if (!nodes) return;
    expectArray(*nodes, pointer + "/nodes");
    for (std::size_t i = 0; i < nodes->size(); ++i) index((*nodes)[i], pointer + "/nodes/" + std::to_string(i), "nodes");
  }

  void checkNode(const Json& node, const std::string& pointer) {
    if (const Json* children = member(node, "children")) {
      expectArray(*children, pointer + "/children");
      for (std::size_t i = 0; i < children->size(); ++i)
        index((*children)[i], pointer + "/children/" + std::to_string(i), "nodes");
    }
    if (const Json* mesh = member(node, "mesh")) index(*mesh, pointer + "/mesh", "meshes");
    if (const Json* camera = member(node, "camera")) index(*camera, pointer + "/camera", "cameras");
    const Json* matrix = member(node, "matrix");
    if (matrix) numbers(*matrix, pointer + "/matrix", 16, -kInf, kInf);
    for (const auto& [key, count] : {std::pair{"translation", 3}, {"rotation", 4}, {"scale", 3}}) {
      const Json* value = member(node, key);
      if (!value) continue;
      numbers(*value, pointer + "/" + key, std::size_t(count), -kInf, kInf);
      if (matrix) fail(pointer + "/" + key, std::string("a node may have a matrix or ") + key + ", not both");
    }
    if (member(node, "skin")) noteIgnored("skins are not part of the model; the mesh is drawn in its bind pose", pointer + "/skin");
    if (member(node, "weights")) noteIgnored("morph weights are not part of the model; ignored", pointer + "/weights");
    const Json* extensions = member(node, "extensions");
    if (!extensions) return;
    expectObject(*extensions, pointer + "/extensions");
    const Json* lights = member(*extensions, kLightsExtension);
    if (!lights) return;
    const std::string at = pointer + "/extensions/" + std::string(kLightsExtension);
    expectObject(*lights, at);
    const Json* light = member(*lights, "light");
    if (!light) fail(at + "/light", "missing required key 'light'");
    index(*light, at + "/light", "lights");
  }

  void checkMesh(const Json& mesh, const std::string& pointer) {
    const Json* primitives = member(mesh, "primitives");
    if (!primitives) fail(pointer + "/primitives", "missing required key 'primitives'");
    expectArray(*primitives, pointer + "/primitives");
    if (primitives->empty()) fail(pointer + "/primitives", "a mesh needs at least one primitive");
    for (std::size_t i = 0; i < primitives->size(); ++i) {
      const std::string at = pointer + "/primitives/" + std::to_string(i);
      const Json& primitive = (*primitives)[i];
      expectObject(primitive, at);
      const Json* attributes = member(primitive, "attributes");
      if (!attributes) fail(at + "/attributes", "missing required key 'attributes'");
      expectObject(*attributes, at + "/attributes");
      for (const auto& item : attributes->items()) index(item.value(), at + "/attributes/" + item.key(), "accessors");
      if (const Json* indices = member(primitive, "indices")) index(*indices, at + "/indices", "accessors");
      if (const Json* mode = member(primitive, "mode")) integer(*mode, at + "/mode", 0, 6);
      if (const Json* material = member(primitive, "material")) index(*material, at + "/material", "materials");
      if (member(primitive, "targets")) noteIgnored("morph targets are not part of the model; ignored", at + "/targets");
    }
  }

  void checkAccessor(const Json& accessor, const std::string& pointer) const {
    if (const Json* view = member(accessor, "bufferView")) index(*view, pointer + "/bufferView", "bufferViews");
    if (const Json* offset = member(accessor, "byteOffset")) integer(*offset, pointer + "/byteOffset", 0, kMaxBytes);
    const Json* componentType = member(accessor, "componentType");
    if (!componentType) fail(pointer + "/componentType", "missing required key 'componentType'");
    const long long component = integer(*componentType, pointer + "/componentType", 5120, 5126);
    if (component == 5124) fail(pointer + "/componentType", "5124 (signed int) is not a glTF 2.0 component type");
    const Json* count = member(accessor, "count");
    if (!count) fail(pointer + "/count", "missing required key 'count'");
    integer(*count, pointer + "/count", 1, kMaxBytes);
    const Json* type = member(accessor, "type");
    static const std::set<std::string> kTypes{"SCALAR", "VEC2", "VEC3", "VEC4", "MAT2", "MAT3", "MAT4"};
    if (!type || !type->is_string() || !kTypes.count(type->get<std::string>())) {
      fail(pointer + "/type", "expected one of SCALAR, VEC2, VEC3, VEC4, MAT2, MAT3, MAT4, got " +
                                  (type ? type->dump() : std::string("nothing")));
    }
    if (const Json* normalized = member(accessor, "normalized")) boolean(*normalized, pointer + "/normalized");
    if (const Json* sparse = member(accessor, "sparse")) expectObject(*sparse, pointer + "/sparse");
  }

  void checkBufferView(const Json& view, const std::string& pointer) const {
    const Json* buffer = member(view, "buffer");
    if (!buffer) fail(pointer + "/buffer", "missing required key 'buffer'");
    index(*buffer, pointer + "/buffer", "buffers");
    if (const Json* offset = member(view, "byteOffset")) integer(*offset, pointer + "/byteOffset", 0, kMaxBytes);
    const Json* length = member(view, "byteLength");
    if (!length) fail(pointer + "/byteLength", "missing required key 'byteLength'");
    integer(*length, pointer + "/byteLength", 1, kMaxBytes);
    if (const Json* stride = member(view, "byteStride")) {
      const long long s = integer(*stride, pointer + "/byteStride", 4, 252);
      if (s % 4 != 0) fail(pointer + "/byteStride", "expected a multiple of 4, got " + std::to_string(s));
    }
  }

  void checkBuffer(const Json& buffer, const std::string& pointer) const {
    const Json* length = member(buffer, "byteLength");
    if (!length) fail(pointer + "/byteLength", "missing required key 'byteLength'");
    integer(*length, pointer + "/byteLength", 1, kMaxBytes);
    if (const Json* uri = member(buffer, "uri"); uri && !uri->is_string())
      fail(pointer + "/uri", "expected a string, got " + describeJsonTypeAndLength(*uri));
  }

  void checkMaterial(const Json& material, const std::string& pointer) {
    if (const Json* pbr = member(material, "pbrMetallicRoughness")) {
      const std::string at = pointer + "/pbrMetallicRoughness";
      expectObject(*pbr, at);
      if (const Json* color = member(*pbr, "baseColorFactor")) numbers(*color, at + "/baseColorFactor", 4, 0, 1);
      if (const Json* metallic = member(*pbr, "metallicFactor")) number(*metallic, at + "/metallicFactor", 0, 1);
      if (const Json* roughness = member(*pbr, "roughnessFactor")) number(*roughness, at + "/roughnessFactor", 0, 1);
      for (const char* texture : {"baseColorTexture", "metallicRoughnessTexture"})
        if (const Json* info = member(*pbr, texture)) checkTextureInfo(*info, at + "/" + texture);
    }
    if (const Json* sided = member(material, "doubleSided")) boolean(*sided, pointer + "/doubleSided");
    for (const char* texture : {"normalTexture", "occlusionTexture", "emissiveTexture"})
      if (const Json* info = member(material, texture)) checkTextureInfo(*info, pointer + "/" + texture);
    if (const Json* emissive = member(material, "emissiveFactor")) {
      numbers(*emissive, pointer + "/emissiveFactor", 3, 0, 1);
      if ((*emissive)[0] != 0 || (*emissive)[1] != 0 || (*emissive)[2] != 0)
        noteIgnored("emission is not part of the model; ignored", pointer + "/emissiveFactor");
    }
    if (const Json* alpha = member(material, "alphaMode"); alpha && *alpha != "OPAQUE")
      noteIgnored("alpha modes are not part of the model; drawn opaque", pointer + "/alphaMode");
    if (const Json* extensions = member(material, "extensions"))
      if (extensions->is_object() && !extensions->empty())
        noteIgnored("material extensions are not part of the model; ignored", pointer + "/extensions");
  }

  // Textures are not part of the model: a reference to one is ignored, and
  // a malformed reference is named, so the author learns of it.
  void checkTextureInfo(const Json& info, const std::string& pointer) {
    noteIgnored("textures are not part of the model; ignored", pointer);
    if (!info.is_object()) {
      warn(pointer, "expected a texture reference object, got " + describeJsonTypeAndLength(info) + "; ignored");
      return;
    }
    const Json* index = member(info, "index");
    if (!index) warn(pointer, "a texture reference without 'index'; ignored");
    else if (!isInteger(*index) || index->get<double>() < 0)
      warn(pointer + "/index", "expected a texture index >= 0, got " + index->dump() + "; ignored");
    if (const Json* texCoord = member(info, "texCoord"); texCoord && (!isInteger(*texCoord) || texCoord->get<double>() < 0))
      warn(pointer + "/texCoord", "expected an integer >= 0, got " + texCoord->dump() + "; ignored");
    for (const char* key : {"scale", "strength"})
      if (const Json* value = member(info, key); value && !value->is_number())
        warn(pointer + "/" + key, "expected a number, got " + describeJsonTypeAndLength(*value) + "; ignored");
    if (const Json* extensions = member(info, "extensions")) {
      if (!extensions->is_object()) {
        warn(pointer + "/extensions", "expected an object, got " + describeJsonTypeAndLength(*extensions) + "; ignored");
      } else {
        for (const auto& item : extensions->items())
          if (!item.value().is_object())
            warn(pointer + "/extensions/" + item.key(), "expected an object, got " + describeJsonTypeAndLength(item.value()) + "; ignored");
      }
    }
  }

  void checkCamera(const Json& camera, const std::string& pointer) const {
    const Json* type = member(camera, "type");
    const std::string name = type && type->is_string() ? type->get<std::string>() : "";
    if (name != "perspective" && name != "orthographic")
      fail(pointer + "/type", "expected perspective or orthographic, got " + (type ? type->dump() : std::string("nothing")));
    const Json* body = member(camera, name);
    const std::string at = pointer + "/" + name;
    if (!body) fail(at, "missing required key '" + name + "'");
    expectObject(*body, at);
    auto required = [&](const char* key, double min, double max, bool minOpen) {
      const Json* value = member(*body, key);
      if (!value) fail(at + "/" + key, std::string("missing required key '") + key + "'");
      return number(*value, at + "/" + key, min, max, minOpen);
    };
    if (name == "perspective") {
      required("yfov", 0, std::numbers::pi, true);
      const double znear = required("znear", 0, kInf, true);
      if (const Json* zfar = member(*body, "zfar")) number(*zfar, at + "/zfar", znear, kInf, true);
      if (const Json* aspect = member(*body, "aspectRatio")) number(*aspect, at + "/aspectRatio", 0, kInf, true);
    } else {
      required("xmag", -kInf, kInf, false);
      const double ymag = required("ymag", -kInf, kInf, false);
      if (ymag == 0) fail(at + "/ymag", "ymag must not be 0");
      const double znear = required("znear", 0, kInf, false);
      required("zfar", znear, kInf, true);
    }
  }

  // Byte counts and offsets beyond this are not a file lightcts can hold.
  static constexpr long long kMaxBytes = 1LL << 40;

  const Json& root_;
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
