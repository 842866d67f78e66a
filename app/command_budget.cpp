// `lightcts budget` (SPEC 5.5): where a frame's light budgets bite, as maps
// and numbers (reference/light_budget.h computes them; budget_maps.h draws
// them). docs/cli.md describes the files.
#include "app/commands.h"
#include "app/exit_status.h"
#include "app/scene_input.h"
#include "imaging/image_codec_loader.h"
#include "imaging/image_files.h"
#include "reference/light_budget.h"
#include "runner/budget_files.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <ostream>

namespace app {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

int runBudgetCommand(const SceneArguments& args, bool allFrames, const std::string& outDir, std::ostream& out,
                     std::ostream& err) {
  return guardCommand(err, [&] {
    if (allFrames && args.frameGiven) throw InputError("--frame and --all-frames exclude each other");
    const SceneInput input = loadSceneInput(args);
    imaging::requireImageModule();
    makeOutputDirectory(outDir);
    const reference::ReferenceRenderer renderer(input.prepared);
    // SPEC 5.5: an animated scene gives every frame unless --frame picks one.
    const bool everyFrame = allFrames || (!args.frameGiven && input.prepared->scene.frames.count > 1);
    const int frames = everyFrame ? input.prepared->scene.frames.count : 1;
    Json framesJson = Json::array();
    std::vector<reports::Rgb8Image> strip;
    std::optional<imaging::Image> previousLoss;
    for (int f = 0; f < frames; ++f) {
      const lighting::Frame frame = everyFrame ? lighting::prepareFrame(input.prepared, f) : input.frame;
      const reference::LightBudget budget = reference::computeLightBudget(renderer, frame);
      std::optional<double> popping;
      if (previousLoss) popping = runner::budgetPoppingScore(*previousLoss, budget.lossRgb);
      previousLoss = budget.lossRgb;
      const fs::path dir = everyFrame ? fs::path(outDir) / ("frame-" + std::to_string(f)) : fs::path(outDir);
      runner::writeBudgetFrameFiles(dir, budget);
      framesJson.push_back(runner::budgetFrameRecord(frame, budget, popping).toJson());
      if (everyFrame) strip.push_back(runner::smallKeptMap(budget));
      out << "budget: " << frame.scene().name << " frame " << frame.index << ": " << budget.pixelsCut
          << " pixel(s) where a budget cuts a light, largest loss " << budget.largestLoss << "\n";
    }
    if (everyFrame) reports::writeRgb8Png((fs::path(outDir) / "kept-strip.png").string(), reports::stripOf(strip));
    const Json document = {{"scene", input.prepared->scene.name},
                           {"width", input.frame.view.width},
                           {"height", input.frame.view.height},
                           {"count_scale", {0, 1, 2, 4, 8, 16, 32, 64}},
                           {"loss", "luminance(ideal - model), 0.2126 R + 0.7152 G + 0.0722 B (SPEC 1)"},
                           {"frames", framesJson}};
    std::ofstream((fs::path(outDir) / "budget.json").string()) << document.dump(2) << "\n";
    out << "budget: written to " << outDir << "\n";
    return kExitSuccess;
  });
}

}  // namespace app
