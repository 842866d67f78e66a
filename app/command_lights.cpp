#include "app/commands.h"
#include "app/exit_status.h"
#include "app/scene_input.h"
#include "lighting/selection_json.h"

#include <ostream>

namespace app {

// SPEC 5.4: the selection of one frame as JSON on stdout.
int runLightsCommand(const SceneArguments& args, std::ostream& out, std::ostream& err) {
  return guardCommand(err, [&] {
    const SceneInput input = loadSceneInput(args, /*bake=*/false);  // selection needs no maps
    out << lighting::selectionToJson(input.frame).dump(2) << "\n";
    return kExitSuccess;
  });
}

}  // namespace app
