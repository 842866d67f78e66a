#include "runner/budget_files.h"

#include "imaging/image_files.h"

#include <algorithm>
#include <cmath>

namespace runner {

namespace fs = std::filesystem;

// The strip's maps are at most this wide: every frame of a path side by side.
constexpr int kStripMapWidth = 96;

results::BudgetFrameRecord budgetFrameRecord(const lighting::Frame& frame, const reference::LightBudget& budget,
                                             std::optional<double> poppingScore) {
  results::BudgetFrameRecord record{frame.index,
                                    budget.pixelsCut,
                                    results::measuredOf(budget.largestLoss),
                                    results::measuredOf(budget.summedLoss),
                                    results::measuredOf(budget.largestRelativeLoss),
                                    poppingScore ? results::measuredOf(*poppingScore) : std::nullopt,
                                    std::vector<results::BudgetLightRecord>{}};
  for (const reference::LightBudgetOfLight& l : budget.lights)
    record.lights->push_back({l.light, frame.scene().lights[std::size_t(l.light)].name, l.reachPixels, l.keptPixels,
                              l.vertexPixels, l.reachPixels - l.keptPixels, l.frameCutPixels, l.objectCutPixels});
  return record;
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
