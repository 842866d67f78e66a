#include "runner/run_budgets.h"

#include "baking/bake.h"
#include "reference/light_budget.h"
#include "reports/budget_maps.h"
#include "runner/budget_files.h"
#include "scene_input/scene_loader.h"

#include <optional>

namespace runner {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

namespace {

Json sceneBudget(const BudgetScene& scene, const fs::path& outDir) {
  const auto prepared = baking::prepareBakedScene(scene_input::loadSceneFile(scene.file.string()));
  const reference::ReferenceRenderer renderer(prepared);
  const int frames = prepared->scene.frames.count;
  Json summaries = Json::array();
  std::vector<reports::Rgb8Image> strip;
  std::optional<imaging::Image> previousLoss;
  std::optional<reference::LightBudget> worst;  // the frame that cuts at the most pixels
  Json worstJson;
  std::int64_t cutAnywhere = 0;
  for (int f = 0; f < frames; ++f) {
    const lighting::Frame frame = lighting::prepareFrame(prepared, f);
    reference::LightBudget budget = reference::computeLightBudget(renderer, frame);
    std::optional<double> popping;
    if (previousLoss) popping = budgetPoppingScore(*previousLoss, budget.lossRgb);
    previousLoss = budget.lossRgb;
    Json summary = budgetFrameJson(frame, budget, popping);
    cutAnywhere += budget.pixelsCut;
    if (frames > 1) strip.push_back(smallKeptMap(budget));
    if (!worst || budget.pixelsCut > worst->pixelsCut) {
      worstJson = summary;
      worst = std::move(budget);
    }
    summary.erase("lights");  // per light: the worst frame's, below
    summaries.push_back(std::move(summary));
  }
  if (cutAnywhere == 0) return {{"cuts", false}, {"frames", summaries}};
  const fs::path dir = fs::path("budgets") / scene.caseName;
  writeBudgetFrameFiles(outDir / dir, *worst);
  Json images = {{"reach", (dir / "reach.png").string()},
                 {"kept", (dir / "kept.png").string()},
                 {"loss", (dir / "loss.png").string()}};
  if (frames > 1) {
    reports::writeRgb8Png((outDir / dir / "kept-strip.png").string(), reports::stripOf(strip));
    images["kept_strip"] = (dir / "kept-strip.png").string();
  }
  Json notKept = Json::array();
  for (const Json& light : worstJson["lights"])
    if (light["not_kept_pixels"].get<std::int64_t>() > 0) notKept.push_back(light);
  return {{"cuts", true},
          {"frames", summaries},
          {"maps_frame", worstJson["frame"]},
          {"images", images},
          {"lights_not_kept", notKept}};
}

}  // namespace

Json runBudgets(const std::vector<BudgetScene>& scenes, const fs::path& outDir) {
  Json budgets = Json::object();
  for (const BudgetScene& scene : scenes) {
    try {
      budgets[scene.caseName] = sceneBudget(scene, outDir);
    } catch (const std::exception& e) {
      budgets[scene.caseName] = {{"error", e.what()}};
    }
  }
  return budgets;
}

}  // namespace runner
