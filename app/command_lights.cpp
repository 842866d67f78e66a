#include "app/commands.h"
#include "app/exit_status.h"
#include "app/scene_input.h"
#include "lighting/selection_json.h"
#include "scene_input/gltf_import.h"
#include "scene_input/gltf_scene_json.h"

#include <filesystem>
#include <ostream>

namespace app {

// SPEC 5.4: the selection of one frame as JSON on stdout; with --scene-json,
// a glTF file's scene as a scene file instead.
int runLightsCommand(const SceneArguments& args, bool sceneJson, std::ostream& out, std::ostream& err) {
  return guardCommand(err, [&] {
    if (sceneJson && !scene_input::isGltfPath(args.scenePath))
      throw InputError("--scene-json prints the scene of a glTF file (.gltf or .glb); " + args.scenePath +
                       " is a scene file already");
    const SceneInput input = loadSceneInput(args, /*bake=*/false);  // selection needs no maps
    if (sceneJson) {
      // Absolute: the output is meant to be saved anywhere.
      const std::string gltf = std::filesystem::absolute(args.scenePath).lexically_normal().string();
      out << scene_input::bareGltfSceneJson(input.prepared->scene, gltf).dump(2) << "\n";
      return kExitSuccess;
    }
    out << lighting::selectionToJson(input.frame).dump(2) << "\n";
    return kExitSuccess;
  });
}

}  // namespace app
