// glTF 2.0 content brought into a scene (SPEC 2.1): the meshes of one glTF
// scene as world-space triangles, its KHR_lights_punctual lights and its
// cameras. The file is read by tinygltf (containers, buffers, data URIs); every
// check that tinygltf 2.7 leaves out (index and byte ranges, non-finite values,
// node cycles, the shape of the JSON that the model reads) is made here, so a
// file that imports is one the model can draw. docs/scene-format.md lists the
// choices SPEC 2.1 leaves open.
#pragma once

#include "lighting/mesh.h"
#include "lighting/scene.h"
#include "scene_input/json_locations.h"

#include <glm/mat4x4.hpp>

#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace scene_input {

// A fault of the glTF file, at an RFC 6901 pointer into its JSON ("" for the
// whole file), and where its text is when the reader knows it (a syntax
// error); otherwise the scene loader locates the pointer in a .gltf text. It
// exits 2.
class GltfError : public std::runtime_error {
 public:
  GltfError(std::string file, std::string pointer, std::string message, TextPosition where = {});
  const std::string& file() const { return file_; }
  const std::string& pointer() const { return pointer_; }
  const std::string& message() const { return message_; }
  TextPosition where() const { return where_; }

 private:
  std::string file_, pointer_, message_;
  TextPosition where_;
};

struct GltfImportRequest {
  std::string file;               // as resolved against the scene file's folder
  std::optional<int> scene;       // absent: the file's `scene`, else 0
  glm::dmat4 transform{1.0};      // the import's transform, applied on top of the hierarchy
};

// One primitive of one node, in world space, with the glTF material it names.
struct ImportedPrimitive {
  std::string name;               // "<node name or #index>/<primitive index>"
  std::string pointer;            // "/meshes/M/primitives/P"
  std::shared_ptr<const lighting::Mesh> mesh;
  lighting::Vec3 baseColor{1, 1, 1};        // baseColorFactor.rgb, clamped to [0, 1]
  double metallic = 1;            // metallicFactor
  double roughness = 1;           // roughnessFactor
};

// A KHR_lights_punctual light at its node: SPEC 2.1's mapping, before the
// scene's light_defaults fill in what glTF has no word for.
struct ImportedLight {
  std::string name;               // the light's name, else "<node name or #index>"
  std::string pointer;            // "/extensions/KHR_lights_punctual/lights/L"
  lighting::LightType type = lighting::LightType::Point;
  lighting::Vec3 position{0, 0, 0};         // the node's world origin
  lighting::Vec3 direction{0, 0, -1};       // normalize(world 3x3 * (0, 0, -1))
  lighting::Vec3 color{1, 1, 1};
  double intensity = 1;
  std::optional<double> range;    // absent: the scene's light_defaults.range
  double spotAngleDeg = 90;       // 2 x outerConeAngle (default pi/4)
  double innerSpotAngleDeg = 0;   // 2 x innerConeAngle
};

// A camera at its node (the first node in the scene's depth-first order that
// carries it). Perspective or orthographic, as glTF defines them.
struct ImportedCamera {
  std::string pointer;            // "/cameras/C"
  lighting::Vec3 position{0, 0, 0};
  lighting::Vec3 forward{0, 0, -1};         // local -Z
  lighting::Vec3 up{0, 1, 0};               // local +Y
  bool perspective = true;
  double yfovRad = 0.8;           // perspective
  double ymag = 1;                // orthographic: half the view's height
  double znear = 0.1;
  std::optional<double> zfar;     // absent: infinite (perspective only)
};

struct GltfContent {
  std::vector<ImportedPrimitive> primitives;  // SPEC 2.1's object order
  std::vector<ImportedLight> lights;          // in node order
  std::vector<std::optional<ImportedCamera>> cameras;  // by camera index; empty when no node carries it
  std::vector<std::string> warnings;          // "FILE: /pointer: what was ignored"
  lighting::Vec3 boundsMin{0, 0, 0}, boundsMax{0, 0, 0};  // of every imported triangle (world space)
  std::size_t triangles = 0;
  std::string file;  // the request's
  // The .gltf's JSON text, null for a .glb (its JSON is a chunk of a binary
  // file: no line and column of it), kept so that a fault found in the
  // content after the import names its line and column without reading the
  // file again.
  std::shared_ptr<const std::string> jsonText;
  TextPosition positionOf(const std::string& pointer) const;  // {} when unknown
};

// SPEC 2.1: more triangles than this, after strips, fans and double-sided
// materials are expanded, is an error.
constexpr std::size_t kMaxImportedTriangles = 4'000'000;

// Reads and checks the file; throws GltfError.
GltfContent importGltf(const GltfImportRequest& request);

// Whether `path` names a glTF file by its extension (.gltf or .glb, any case):
// such a file given as a scene is read as SPEC 2.1's bare import.
bool isGltfPath(const std::string& path);

}  // namespace scene_input
