#include "scene_input/gltf_import.h"

#include "scene_input/gltf_accessors.h"
#include "scene_input/gltf_json_checks.h"
#include "scene_input/imported_mesh.h"
#include "scene_input/json_input.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat3x3.hpp>
#include <tiny_gltf.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <numeric>
#include <sstream>

namespace scene_input {

using namespace lighting;  // the model this folder reads scenes into

GltfError::GltfError(std::string file, std::string pointer, std::string message, TextPosition where)
    : std::runtime_error(file + ": " + (pointer.empty() ? "" : pointer + ": ") + message),
      file_(std::move(file)),
      pointer_(std::move(pointer)),
      message_(std::move(message)),
      where_(where) {}

bool isGltfPath(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return extension == ".gltf" || extension == ".glb";
}

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

constexpr std::string_view kLightsExtension = "KHR_lights_punctual";

std::vector<unsigned char> readBytes(const std::string& file) {
  std::error_code ignored;
  if (fs::is_directory(file, ignored)) throw GltfError(file, "", "cannot read the glTF file: it is a directory");
  errno = 0;
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    throw GltfError(file, "", std::string("cannot open the glTF file") +
                                  (errno != 0 ? std::string(" (") + std::strerror(errno) + ")" : ""));
  }
  std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw GltfError(file, "", "cannot read the glTF file");
  return bytes;
}

std::uint32_t littleEndian32(const unsigned char* p) {
  return std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 | std::uint32_t(p[3]) << 24;
}

bool isGlb(const std::vector<unsigned char>& bytes) {
  return bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
}

// The JSON chunk of a GLB container (glTF 2.0, "GLB File Format"): a 12-byte
// header (magic, version 2, length) and a first chunk of type JSON.
std::string glbJson(const std::vector<unsigned char>& bytes, const std::string& file) {
  auto bad = [&](const std::string& why) { return GltfError(file, "", "invalid GLB container: " + why); };
  if (bytes.size() < 20) throw bad("shorter than its 12-byte header and a chunk header");
  if (littleEndian32(&bytes[4]) != 2) throw bad("version " + std::to_string(littleEndian32(&bytes[4])) + ", expected 2");
  if (littleEndian32(&bytes[8]) > bytes.size())
    throw bad("the header says " + std::to_string(littleEndian32(&bytes[8])) + " bytes, the file has " +
              std::to_string(bytes.size()));
  const std::uint32_t length = littleEndian32(&bytes[12]);
  if (littleEndian32(&bytes[16]) != 0x4E4F534Au) throw bad("the first chunk is not JSON");
  if (length > bytes.size() - 20) throw bad("the JSON chunk runs past the end of the file");
  return std::string(bytes.begin() + 20, bytes.begin() + 20 + length);
}

// The JSON read as every input's is (scene_input/json_input.h): invalid
// JSON, non-finite numbers and repeated keys refused with their place.
Json parseDocument(const std::string& text, const std::string& file) {
  try {
    return readJsonInput<Json>(text, "a glTF file");
  } catch (const JsonInputError& error) {
    throw GltfError(file, error.pointer(), error.message(), error.where());
  }
}

// RFC 3986 percent-decoding of a relative URI.
std::string percentDecoded(const std::string& uri) {
  std::string out;
  for (std::size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '%' && i + 2 < uri.size() && std::isxdigit((unsigned char)uri[i + 1]) &&
        std::isxdigit((unsigned char)uri[i + 2])) {
      out += char(std::stoi(uri.substr(i + 1, 2), nullptr, 16));
      i += 2;
    } else {
      out += uri[i];
    }
  }
  return out;
}

// External buffers are looked for beside the glTF file only (tinygltf would
// also try the working directory, where an unrelated file of the same name
// could stand in), and must hold exactly byteLength bytes (tinygltf 2.7
// refuses a longer file although glTF allows one).
void checkExternalBuffers(const Json& document, const std::string& file) {
  const auto buffers = document.find("buffers");
  if (buffers == document.end()) return;
  for (std::size_t i = 0; i < buffers->size(); ++i) {
    const Json& buffer = (*buffers)[i];
    const auto uri = buffer.find("uri");
    if (uri == buffer.end() || uri->get<std::string>().rfind("data:", 0) == 0) continue;
    const std::string pointer = "/buffers/" + std::to_string(i);
    const fs::path path = fs::path(file).parent_path() / percentDecoded(uri->get<std::string>());
    std::error_code error;
    const auto size = fs::file_size(path, error);
    if (error) throw GltfError(file, pointer + "/uri", "cannot read the buffer file '" + path.string() + "': " + error.message());
    const auto length = buffer["byteLength"].get<std::uintmax_t>();
    if (size != length) {
      throw GltfError(file, pointer + "/byteLength",
                      "the buffer file '" + path.string() + "' has " + std::to_string(size) + " bytes, byteLength says " +
                          std::to_string(length) + (size > length ? " (tinygltf reads only files of exactly byteLength)" : ""));
    }
  }
}

// tinygltf's messages quote a data URI whole; keep its start only.
std::string shortened(std::string message) {
  for (std::size_t at = message.find("data:"); at != std::string::npos; at = message.find("data:", at + 1)) {
    std::size_t end = at;
    while (end < message.size() && !std::isspace((unsigned char)message[end])) ++end;
    if (end - at > 48) message.replace(at + 40, end - at - 40, "...");
  }
  while (!message.empty() && std::isspace((unsigned char)message.back())) message.pop_back();
  return message;
}

// Images are not part of the model: tinygltf is told not to decode them.
bool skipImage(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*) {
  return true;
}

// The bytes of every buffer, through tinygltf (GLB chunks, data URIs,
// external files).
GltfBuffers loadBuffers(const std::vector<unsigned char>& bytes, const std::string& text, bool glb,
                        const std::string& file, std::size_t bufferCount) {
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(skipImage, nullptr);
  tinygltf::Model model;
  std::string err, warn;
  const std::string baseDir = fs::path(file).parent_path().string();
  const bool ok = glb ? loader.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(), unsigned(bytes.size()), baseDir)
                      : loader.LoadASCIIFromString(&model, &err, &warn, text.data(), unsigned(text.size()), baseDir);
  if (!ok) {
    // Buffers are read in order and kept only when whole: a short list names the one that failed.
    const std::string pointer = model.buffers.size() < bufferCount ? "/buffers/" + std::to_string(model.buffers.size()) : "";
    throw GltfError(file, pointer, "tinygltf cannot read the file: " + shortened(err.empty() ? warn : err));
  }
  GltfBuffers buffers;
  for (tinygltf::Buffer& buffer : model.buffers) buffers.push_back(std::move(buffer.data));
  return buffers;
}

glm::dmat4 localMatrix(const Json& node, const std::string& file, const std::string& pointer,
                       std::vector<std::string>& warnings) {
  if (const auto m = node.find("matrix"); m != node.end()) {
    double values[16];
    for (int i = 0; i < 16; ++i) values[i] = (*m)[i].get<double>();
    return glm::make_mat4(values);  // column-major, as glTF stores it
  }
  glm::dmat4 local(1.0);
  if (const auto t = node.find("translation"); t != node.end())
    local = glm::translate(local, Vec3((*t)[0].get<double>(), (*t)[1].get<double>(), (*t)[2].get<double>()));
  if (const auto r = node.find("rotation"); r != node.end()) {
    glm::dquat q((*r)[3].get<double>(), (*r)[0].get<double>(), (*r)[1].get<double>(), (*r)[2].get<double>());
    const double length = glm::length(q);
    if (!(length > 0) || !std::isfinite(length)) throw GltfError(file, pointer + "/rotation", "the rotation quaternion has no length");
    if (std::abs(length - 1) > 1e-3)
      warnings.push_back(file + ": " + pointer + "/rotation: the quaternion is not unit (length " +
                         std::to_string(length) + "); normalised");
    local = local * glm::mat4_cast(q / length);
  }
  if (const auto s = node.find("scale"); s != node.end())
    local = glm::scale(local, Vec3((*s)[0].get<double>(), (*s)[1].get<double>(), (*s)[2].get<double>()));
  return local;
}

bool finite(const glm::dmat4& m) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(m[c][r])) return false;
  return true;
}

Vec3 unitOr(const Vec3& v, const Vec3& fallback) {
  const double length = glm::length(v);
  return length > 0 && std::isfinite(length) ? v / length : fallback;
}

class Importer {
 public:
  Importer(const GltfImportRequest& request, const Json& document, const GltfBuffers& buffers)
      : request_(request), doc_(document), accessors_(document, buffers, request.file), file_(request.file) {}

  GltfContent run(std::vector<std::string> warnings) {
    content_.warnings = std::move(warnings);
    const std::size_t nodeCount = doc_.contains("nodes") ? doc_["nodes"].size() : 0;
    state_.assign(nodeCount, Unvisited);
    if (doc_.contains("cameras")) content_.cameras.resize(doc_["cameras"].size());
    const std::size_t sceneCount = doc_.contains("scenes") ? doc_["scenes"].size() : 0;
    int scene = doc_.contains("scene") ? doc_["scene"].get<int>() : 0;
    if (request_.scene) {
      scene = *request_.scene;
      if (std::size_t(scene) >= sceneCount)
        throw GltfError(file_, "/scenes", "the import asks for scene " + std::to_string(scene) + ", the file has " +
                                              std::to_string(sceneCount));
    }
    if (sceneCount == 0) {
      warn("", "the file has no scenes; nothing is imported");
      return std::move(content_);
    }
    const Json& roots = doc_["scenes"][std::size_t(scene)].value("nodes", Json::array());
    if (roots.empty()) warn("/scenes/" + std::to_string(scene), "the scene has no nodes; nothing is imported");
    for (std::size_t i = 0; i < roots.size(); ++i)
      visit(roots[i].get<int>(), request_.transform, "/scenes/" + std::to_string(scene) + "/nodes/" + std::to_string(i));
    if (content_.triangles == 0 && !roots.empty()) warn("", "the scene has no triangles to draw");
    return std::move(content_);
  }

 private:
  enum State { Unvisited, OnPath, Done };

  void warn(const std::string& pointer, const std::string& message) {
    content_.warnings.push_back(file_ + ": " + (pointer.empty() ? "" : pointer + ": ") + message);
  }

  void visit(int node, const glm::dmat4& parentWorld, const std::string& reachedAt) {
    if (state_[node] == OnPath)
      throw GltfError(file_, reachedAt, "node " + std::to_string(node) + " is its own ancestor (a cycle)");
    if (state_[node] == Done)
      throw GltfError(file_, reachedAt, "node " + std::to_string(node) + " is reached twice (glTF nodes form disjoint trees)");
    state_[node] = OnPath;
    const std::string pointer = "/nodes/" + std::to_string(node);
    const Json& n = doc_["nodes"][std::size_t(node)];
    const glm::dmat4 world = parentWorld * localMatrix(n, file_, pointer, content_.warnings);
    if (!finite(world)) throw GltfError(file_, pointer, "the node's world transform is not finite");
    const std::string name = n.contains("name") && n["name"].is_string() && !n["name"].get<std::string>().empty()
                                 ? n["name"].get<std::string>()
                                 : "#" + std::to_string(node);
    if (n.contains("mesh")) addMesh(n["mesh"].get<int>(), world, name, pointer);
    if (n.contains("camera")) addCamera(n["camera"].get<int>(), world);
    if (n.contains("extensions") && n["extensions"].contains(kLightsExtension))
      addLight(n["extensions"][kLightsExtension]["light"].get<int>(), world, name, pointer);
    const Json& children = n.value("children", Json::array());
    for (std::size_t i = 0; i < children.size(); ++i)
      visit(children[i].get<int>(), world, pointer + "/children/" + std::to_string(i));
    state_[node] = Done;
  }

  void addMesh(int meshIndex, const glm::dmat4& world, const std::string& nodeName, const std::string& nodePointer) {
    const glm::dmat3 linear(world);
    const double determinant = glm::determinant(linear);
    const Json& primitives = doc_["meshes"][std::size_t(meshIndex)]["primitives"];
    if (!(std::abs(determinant) > 0) || !std::isfinite(determinant)) {
      warn(nodePointer, "the world transform is singular (a scale of 0?): its mesh has no area and is skipped");
      return;
    }
    const glm::dmat3 normalMatrix = glm::inverseTranspose(linear);
    for (std::size_t p = 0; p < primitives.size(); ++p) {
      const std::string pointer = "/meshes/" + std::to_string(meshIndex) + "/primitives/" + std::to_string(p);
      addPrimitive(primitives[p], pointer, world, normalMatrix, determinant < 0, nodeName + "/" + std::to_string(p));
    }
  }

  void addPrimitive(const Json& primitive, const std::string& pointer, const glm::dmat4& world,
                    const glm::dmat3& normalMatrix, bool mirrored, const std::string& name) {
    const int mode = primitive.value("mode", 4);
    if (mode < 4) {
      static const char* kModes[] = {"points", "lines", "line loops", "line strips"};
      warn(pointer + "/mode", std::string(kModes[mode]) + " are outside the model; the primitive is skipped");
      return;
    }
    const Json& attributes = primitive["attributes"];
    if (!attributes.contains("POSITION")) {
      warn(pointer + "/attributes", "the primitive has no POSITION; skipped");
      return;
    }
    WorldPrimitive world_;
    const std::vector<Vec3> positions = accessors_.readVec3(attributes["POSITION"].get<int>(), "POSITION");
    std::vector<std::uint32_t> indices;
    std::string indicesPointer = pointer + "/attributes/POSITION";
    if (primitive.contains("indices")) {
      indices = accessors_.readIndices(primitive["indices"].get<int>(), positions.size());
      indicesPointer = pointer + "/indices";
    } else {
      indices.resize(positions.size());
      std::iota(indices.begin(), indices.end(), 0u);
    }
    if (mode == 4 && indices.size() % 3 != 0)
      throw GltfError(file_, indicesPointer, "TRIANGLES needs a multiple of 3 vertices, got " + std::to_string(indices.size()));
    if (indices.size() < 3)
      throw GltfError(file_, indicesPointer, "a triangle primitive needs at least 3 vertices, got " + std::to_string(indices.size()));
    const Json material = primitive.contains("material") ? doc_["materials"][primitive["material"].get<std::size_t>()]
                                                         : Json::object();
    const bool doubleSided = material.value("doubleSided", false);
    const std::size_t expected = (mode == 4 ? indices.size() / 3 : indices.size() - 2) * (doubleSided ? 2 : 1);
    if (content_.triangles + expected > kMaxImportedTriangles) {
      throw GltfError(file_, pointer, "the import has more than " + std::to_string(kMaxImportedTriangles) +
                                          " triangles after expansion (SPEC 2.1's limit)");
    }
    world_.triangles = trianglesOf(TriangleMode(mode), indices);
    world_.positions.reserve(positions.size());
    for (const Vec3& p : positions) {
      const Vec3 w = Vec3(world * glm::dvec4(p, 1.0));
      if (!std::isfinite(w.x) || !std::isfinite(w.y) || !std::isfinite(w.z))
        throw GltfError(file_, pointer + "/attributes/POSITION", "a vertex's world position is not finite");
      world_.positions.push_back(w);
    }
    if (attributes.contains("NORMAL")) {
      const std::vector<Vec3> normals = accessors_.readVec3(attributes["NORMAL"].get<int>(), "NORMAL");
      if (normals.size() != positions.size()) {
        throw GltfError(file_, pointer + "/attributes/NORMAL", "NORMAL has " + std::to_string(normals.size()) +
                                                                   " elements, POSITION " + std::to_string(positions.size()));
      }
      world_.normals.emplace();
      world_.normals->reserve(normals.size());
      for (const Vec3& n : normals) world_.normals->push_back(normalMatrix * n);
    }
    world_.reverseWinding = mirrored;
    world_.doubleSided = doubleSided;
    std::size_t zeroNormals = 0;
    auto mesh = std::make_shared<Mesh>(buildImportedMesh(std::move(world_), &zeroNormals));
    if (zeroNormals > 0)
      warn(pointer + "/attributes/NORMAL", std::to_string(zeroNormals) +
                                               " normals have no length; each takes the normal of its triangles");
    if (mesh->triangles.empty()) {
      warn(pointer, "no triangle of the primitive has an area; skipped");
      return;
    }
    ImportedPrimitive out;
    out.name = name;
    out.pointer = pointer;
    const Json pbr = material.value("pbrMetallicRoughness", Json::object());
    if (pbr.contains("baseColorFactor")) {
      const Json& c = pbr["baseColorFactor"];
      out.baseColor = glm::clamp(Vec3(c[0].get<double>(), c[1].get<double>(), c[2].get<double>()), 0.0, 1.0);
    }
    out.metallic = pbr.value("metallicFactor", 1.0);
    out.roughness = pbr.value("roughnessFactor", 1.0);
    if (content_.primitives.empty()) {
      content_.boundsMin = mesh->boundsMin;
      content_.boundsMax = mesh->boundsMax;
    }
    content_.boundsMin = glm::min(content_.boundsMin, mesh->boundsMin);
    content_.boundsMax = glm::max(content_.boundsMax, mesh->boundsMax);
    content_.triangles += mesh->triangles.size();
    out.mesh = std::move(mesh);
    content_.primitives.push_back(std::move(out));
  }

  void addLight(int index, const glm::dmat4& world, const std::string& nodeName, const std::string& nodePointer) {
    const Json& light = doc_["extensions"][kLightsExtension]["lights"][std::size_t(index)];
    ImportedLight out;
    out.pointer = "/extensions/" + std::string(kLightsExtension) + "/lights/" + std::to_string(index);
    out.name = light.contains("name") && light["name"].is_string() && !light["name"].get<std::string>().empty()
                   ? light["name"].get<std::string>()
                   : nodeName;
    const std::string type = light["type"].get<std::string>();
    out.type = type == "directional" ? LightType::Directional : type == "point" ? LightType::Point : LightType::Spot;
    out.position = Vec3(world * glm::dvec4(0, 0, 0, 1));
    const Vec3 direction = glm::dmat3(world) * Vec3(0, 0, -1);
    if (!(glm::length(direction) > 0))
      throw GltfError(file_, nodePointer, "the light's node has a singular transform: no direction");
    out.direction = glm::normalize(direction);
    if (light.contains("color")) {
      const Json& c = light["color"];
      out.color = Vec3(c[0].get<double>(), c[1].get<double>(), c[2].get<double>());
    }
    out.intensity = light.value("intensity", 1.0);
    if (light.contains("range")) out.range = light["range"].get<double>();
    if (out.type == LightType::Spot) {
      const Json& spot = light["spot"];
      constexpr double kDegrees = 180.0 / std::numbers::pi;
      out.spotAngleDeg = 2 * spot.value("outerConeAngle", std::numbers::pi / 4) * kDegrees;
      out.innerSpotAngleDeg = 2 * spot.value("innerConeAngle", 0.0) * kDegrees;
    }
    content_.lights.push_back(std::move(out));
  }

  void addCamera(int index, const glm::dmat4& world) {
    std::optional<ImportedCamera>& slot = content_.cameras[std::size_t(index)];
    if (slot) return;  // the first node that carries it
    const Json& camera = doc_["cameras"][std::size_t(index)];
    ImportedCamera out;
    out.pointer = "/cameras/" + std::to_string(index);
    out.position = Vec3(world * glm::dvec4(0, 0, 0, 1));
    const glm::dmat3 linear(world);
    out.forward = unitOr(linear * Vec3(0, 0, -1), Vec3(0, 0, -1));
    out.up = unitOr(linear * Vec3(0, 1, 0), Vec3(0, 1, 0));
    out.perspective = camera["type"] == "perspective";
    const Json& body = camera[out.perspective ? "perspective" : "orthographic"];
    out.znear = body["znear"].get<double>();
    if (body.contains("zfar")) out.zfar = body["zfar"].get<double>();
    if (out.perspective) out.yfovRad = body["yfov"].get<double>();
    else out.ymag = std::abs(body["ymag"].get<double>());
    slot = out;
  }

  const GltfImportRequest& request_;
  const Json& doc_;
  GltfAccessors accessors_;
  std::string file_;
  std::vector<State> state_;
  GltfContent content_;
};

}  // namespace

GltfContent importGltf(const GltfImportRequest& request) {
  const std::string& file = request.file;
  const std::vector<unsigned char> bytes = readBytes(file);
  if (bytes.empty()) throw GltfError(file, "", "the glTF file is empty");
  const bool glb = isGlb(bytes);
  const auto text = std::make_shared<const std::string>(glb ? glbJson(bytes, file) : std::string(bytes.begin(), bytes.end()));
  try {
    const Json document = parseDocument(*text, file);
    std::vector<std::string> warnings;
    checkGltfJson(document, file, warnings);
    checkExternalBuffers(document, file);
    const std::size_t bufferCount = document.contains("buffers") ? document["buffers"].size() : 0;
    const GltfBuffers buffers = loadBuffers(bytes, *text, glb, file, bufferCount);
    if (buffers.size() != bufferCount)
      throw GltfError(file, "/buffers", "tinygltf read " + std::to_string(buffers.size()) + " of " +
                                            std::to_string(bufferCount) + " buffers");
    GltfContent content = Importer(request, document, buffers).run(std::move(warnings));
    content.file = file;
    if (!glb) content.jsonText = text;
    return content;
  } catch (const GltfError& error) {
    // A .glb's JSON is a chunk of a binary file: no line and column of it.
    if (glb && error.where().line != 0) throw GltfError(error.file(), error.pointer(), error.message());
    // The checks name a JSON pointer; its line and column come from the text parsed here.
    if (glb || error.where().line != 0 || error.pointer().empty()) throw;
    throw GltfError(error.file(), error.pointer(), error.message(),
                    locateJsonPointer(*text, error.pointer()).value_or(TextPosition{}));
  }
}

TextPosition GltfContent::positionOf(const std::string& pointer) const {
  if (!jsonText || pointer.empty()) return {};
  return locateJsonPointer(*jsonText, pointer).value_or(TextPosition{});
}

}  // namespace scene_input
