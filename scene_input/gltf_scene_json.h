// A glTF file read as a scene (SPEC 2.1's bare import), written back as a
// scene file a user can copy and edit: the image, the camera, the ambient
// and every light written out (the file's own, or the default rig,
// lighting/default_rig.h), around an import of the file that takes none of
// its lights. Loading the output gives the same scene. `lightcts lights
// --scene FILE.glb --scene-json` prints it (docs/cli.md).
#pragma once

#include "lighting/scene.h"

#include <nlohmann/json.hpp>

#include <string>

namespace scene_input {

// `scene` as loadSceneFile read the glTF file `gltfPath`, whose path the
// import names as it is given.
nlohmann::ordered_json bareGltfSceneJson(const lighting::Scene& scene, const std::string& gltfPath);

}  // namespace scene_input
