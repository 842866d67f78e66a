// One frame's light budgets (SPEC 5.5) as files and JSON: what
// `lightcts budget` writes and what a run's report shows. The numbers come
// from reference/light_budget.h, the pictures from reports/budget_maps.h.
#pragma once

#include "lighting/frame.h"
#include "reference/light_budget.h"
#include "reports/budget_maps.h"
#include "results/budget_records.h"

#include <filesystem>
#include <optional>

namespace runner {

// One frame's budgets with every light: budget.json's entry (docs/cli.md,
// `lightcts budget`) and, without its lights, a run's.
results::BudgetFrameRecord budgetFrameRecord(const lighting::Frame& frame, const reference::LightBudget& budget,
                                             std::optional<double> poppingScore);

// SPEC 6's popping score of the model itself: the largest change, over pixels
// and channels, of its error against the ideal from one frame to the next.
double budgetPoppingScore(const imaging::Image& previousLoss, const imaging::Image& loss);

// dir/reach.png, kept.png, loss.exr and loss.png (creates dir).
void writeBudgetFrameFiles(const std::filesystem::path& dir, const reference::LightBudget& budget);

// The kept map scaled down (nearest) to at most 96 pixels wide, with its
// legend: one frame of an animated scene's strip.
reports::Rgb8Image smallKeptMap(const reference::LightBudget& budget);

}  // namespace runner
