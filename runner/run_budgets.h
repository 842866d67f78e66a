// The light budgets of a run's scenes (SPEC 5.5) for its report: once per
// scene (they do not depend on the backend), every frame, by the reference.
// A scene whose budgets cut a light somewhere gets its maps in
// OUT/budgets/<group>.<name>/ (kept, reach and loss of the frame that cuts
// most; the kept strip of an animated scene) and its figures in
// results.json's `budgets`; one that cuts nothing gets a one-line entry.
#pragma once

#include "results/budget_records.h"

#include <filesystem>
#include <string>
#include <vector>

namespace runner {

struct BudgetScene {
  std::string caseName;  // <group>.<name>
  std::filesystem::path file;
};

// results.json's `budgets`: {"<group>.<name>": {...}} (docs/results-format.md).
// Image paths are relative to `outDir`.
std::vector<results::SceneBudgetRecord> runBudgets(const std::vector<BudgetScene>& scenes,
                                                   const std::filesystem::path& outDir);

}  // namespace runner
