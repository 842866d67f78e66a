#include "runner/budget_files.h"

#include "imaging/image_files.h"

#include <algorithm>
#include <cmath>

namespace runner {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

// The strip's maps are at most this wide: every frame of a path side by side.
constexpr int kStripMapWidth = 96;

Json budgetFrameJson(const lighting::Frame& frame, const reference::LightBudget& budget,
                     std::optional<double> poppingScore) {
  Json lights = Json::array();
  for (const reference::LightBudgetOfLight& l : budget.lights) {
    lights.push_back({{"light", l.light},
                      {"name", frame.scene().lights[std::size_t(l.light)].name},
                      {"reach_pixels", l.reachPixels},
                      {"kept_pixels", l.keptPixels},
                      {"vertex_pixels", l.vertexPixels},
                      {"not_kept_pixels", l.reachPixels - l.keptPixels},
                      {"not_kept_because",
                       {{std::string(reference::budgetCutName(reference::BudgetCut::Frame)), l.frameCutPixels},
                        {std::string(reference::budgetCutName(reference::BudgetCut::Object)), l.objectCutPixels}}}});
  }
  const auto finite = [](double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); };
  return {{"frame", frame.index},
          {"pixels_cut", budget.pixelsCut},
          {"largest_loss", finite(budget.largestLoss)},
          {"summed_loss", finite(budget.summedLoss)},
          {"largest_relative_loss", finite(budget.largestRelativeLoss)},
          {"popping_score", poppingScore ? finite(*poppingScore) : Json(nullptr)},
          {"lights", lights}};
}

double budgetPoppingScore(const imaging::Image& previousLoss, const imaging::Image& loss) {
  double largest = 0;
  for (std::size_t i = 0; i < loss.pixels.size(); ++i)
    largest = std::max(largest, double(std::abs(loss.pixels[i] - previousLoss.pixels[i])));
  return largest;
}

void writeBudgetFrameFiles(const fs::path& dir, const reference::LightBudget& budget) {
  fs::create_directories(dir);
  reports::writeRgb8Png((dir / "reach.png").string(), reports::countMap(budget.width, budget.height, budget.reach));
  reports::writeRgb8Png((dir / "kept.png").string(), reports::countMap(budget.width, budget.height, budget.kept));
  imaging::writeExr((dir / "loss.exr").string(), budget.lossRgb);
  reports::writeRgb8Png((dir / "loss.png").string(), reports::lossMap(budget.width, budget.height, budget.loss));
}

reports::Rgb8Image smallKeptMap(const reference::LightBudget& budget) {
  const int step = std::max(1, (budget.width + kStripMapWidth - 1) / kStripMapWidth);
  const int w = (budget.width + step - 1) / step, h = (budget.height + step - 1) / step;
  std::vector<int> counts(std::size_t(w) * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      counts[std::size_t(y) * w + x] = budget.kept[std::size_t(y * step) * budget.width + x * step];
  return reports::countMap(w, h, counts);
}

}  // namespace runner
