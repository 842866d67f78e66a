// SPEC 5.5's light budgets as results.json's "budgets" holds them and
// `lightcts budget`'s budget.json writes them (docs/results-format.md,
// docs/cli.md), typed: the runner and the budget command fill them, the
// report reads them. Keys spelled once, in toJson and fromJson.
#pragma once

#include "results/outcome_records.h"

#include <optional>
#include <string>
#include <vector>

namespace results {

// One light of one frame: where it reaches, where the model keeps it, and
// why not elsewhere (cut by the frame's limits, SPEC 5.1, or left out of the
// object's list, SPEC 5.2).
struct BudgetLightRecord {
  long long light = 0;  // its index in the scene
  std::string name;
  long long reachPixels = 0;
  long long keptPixels = 0;
  long long vertexPixels = 0;
  long long notKeptPixels = 0;
  long long cutByFrame = 0;
  long long cutByObject = 0;

  Json toJson() const;
  static BudgetLightRecord fromJson(const Json& json);
};

// One frame's budgets. `lights` is budget.json's (every light); a run's
// frames leave it out (its lights are the maps frame's lightsNotKept).
struct BudgetFrameRecord {
  long long frame = 0;
  long long pixelsCut = 0;
  Measured largestLoss;
  Measured summedLoss;
  Measured largestRelativeLoss;
  Measured poppingScore;  // none on the first frame
  std::optional<std::vector<BudgetLightRecord>> lights;

  Json toJson() const;
  static BudgetFrameRecord fromJson(const Json& json);
};

// A scene's budgets in a run: every frame, and where some light is cut, the
// maps of the frame that cuts at the most pixels and its lights not kept.
struct SceneBudgetRecord {
  std::string scene;  // <group>.<name>
  std::string error;  // why they could not be computed; "" when they were
  bool cuts = false;
  std::vector<BudgetFrameRecord> frames;
  long long mapsFrame = 0;
  std::string reachImage, keptImage, lossImage;  // relative to the run folder
  std::string keptStripImage;                    // animated scenes only
  std::vector<BudgetLightRecord> lightsNotKept;

  Json toJson() const;  // the value under the scene's name
  static SceneBudgetRecord fromJson(const std::string& scene, const Json& json);
};

// results.json's "budgets": one entry per scene, in order.
Json budgetsJson(const std::vector<SceneBudgetRecord>& budgets);
std::vector<SceneBudgetRecord> budgetsFromJson(const Json& json);

}  // namespace results
