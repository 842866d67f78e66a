#include "runner/run_budgets.h"

#include "baking/bake.h"
#include "reference/light_budget.h"
#include "reports/budget_maps.h"
#include "runner/budget_files.h"
#include "runner/run_interruption.h"
#include "scene_input/scene_loader.h"

#include <optional>

namespace runner {

namespace fs = std::filesystem;

namespace {

results::SceneBudgetRecord sceneBudget(const BudgetScene& scene, const fs::path& outDir) {
  const auto prepared = baking::prepareBakedScene(scene_input::loadSceneFile(scene.file.string()));
  const reference::ReferenceRenderer renderer(prepared);
  const int frames = prepared->scene.frames.count;
  results::SceneBudgetRecord record;
  record.scene = scene.caseName;
  std::vector<reports::Rgb8Image> strip;
  std::optional<imaging::Image> previousLoss;
  std::optional<reference::LightBudget> worst;  // the frame that cuts at the most pixels
  results::BudgetFrameRecord worstFrame;
  std::int64_t cutAnywhere = 0;
  for (int f = 0; f < frames; ++f) {
    const lighting::Frame frame = lighting::prepareFrame(prepared, f);
    reference::LightBudget budget = reference::computeLightBudget(renderer, frame);
    std::optional<double> popping;
    if (previousLoss) popping = budgetPoppingScore(*previousLoss, budget.lossRgb);
    previousLoss = budget.lossRgb;
    results::BudgetFrameRecord summary = budgetFrameRecord(frame, budget, popping);
    cutAnywhere += budget.pixelsCut;
    if (frames > 1) strip.push_back(smallKeptMap(budget));
    if (!worst || budget.pixelsCut > worst->pixelsCut) {
      worstFrame = summary;
      worst = std::move(budget);
    }
    summary.lights.reset();  // per light: the worst frame's, below
    record.frames.push_back(std::move(summary));
  }
  if (cutAnywhere == 0) return record;
  record.cuts = true;
  const fs::path dir = fs::path("budgets") / scene.caseName;
  writeBudgetFrameFiles(outDir / dir, *worst);
  record.reachImage = (dir / "reach.png").string();
  record.keptImage = (dir / "kept.png").string();
  record.lossImage = (dir / "loss.png").string();
  if (frames > 1) {
    reports::writeRgb8Png((outDir / dir / "kept-strip.png").string(), reports::stripOf(strip));
    record.keptStripImage = (dir / "kept-strip.png").string();
  }
  record.mapsFrame = worstFrame.frame;
  for (const results::BudgetLightRecord& light : *worstFrame.lights)
    if (light.notKeptPixels > 0) record.lightsNotKept.push_back(light);
  return record;
}

}  // namespace

std::vector<results::SceneBudgetRecord> runBudgets(const std::vector<BudgetScene>& scenes, const fs::path& outDir) {
  std::vector<results::SceneBudgetRecord> budgets;
  for (const BudgetScene& scene : scenes) {
    if (interruptingSignal() != 0) break;  // an interrupted run computes no more
    try {
      budgets.push_back(sceneBudget(scene, outDir));
    } catch (const std::exception& e) {
      results::SceneBudgetRecord failed;
      failed.scene = scene.caseName;
      failed.error = e.what();
      budgets.push_back(std::move(failed));
    }
  }
  return budgets;
}

}  // namespace runner
