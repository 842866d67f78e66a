// The shape of a glTF document's JSON, checked before anything is read from
// it. tinygltf 2.7 quietly keeps a default for a value of the wrong type (a
// `primitives` object becomes no primitives, a `scene` string becomes no
// scene), follows no index it is given, and ignores `extensionsRequired`; so
// the importer checks the raw JSON itself. What the model reads (scenes,
// nodes, meshes, accessors, buffers, materials' factors, cameras,
// KHR_lights_punctual) must be right or the file is refused (GltfError); a
// fault in what the model ignores (a texture reference, a name) is a warning
// that names it.
#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace scene_input {

// Throws GltfError naming `file` and the JSON pointer of the first fault;
// appends "FILE: /pointer: ..." warnings for faults in ignored content and
// for content outside the model (textures, skins, other extensions).
void checkGltfJson(const nlohmann::json& document, const std::string& file, std::vector<std::string>& warnings);

}  // namespace scene_input
