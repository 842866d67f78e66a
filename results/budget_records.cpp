#include "results/budget_records.h"

#include "results/json_fields.h"

namespace results {
namespace {

using namespace fields;

Json lightsJson(const std::vector<BudgetLightRecord>& lights) {
  Json array = Json::array();
  for (const BudgetLightRecord& light : lights) array.push_back(light.toJson());
  return array;
}

}  // namespace

Json BudgetLightRecord::toJson() const {
  return {{"light", light},
          {"name", name},
          {"reach_pixels", reachPixels},
          {"kept_pixels", keptPixels},
          {"vertex_pixels", vertexPixels},
          {"not_kept_pixels", notKeptPixels},
          {"not_kept_because", {{"frame", cutByFrame}, {"object", cutByObject}}}};
}

BudgetLightRecord BudgetLightRecord::fromJson(const Json& json) {
  const Json because = carried(json, "not_kept_because", Json::object());
  return {integer(json, "light"),         text(json, "name"),
          integer(json, "reach_pixels"),  integer(json, "kept_pixels"),
          integer(json, "vertex_pixels"), integer(json, "not_kept_pixels"),
          because.is_object() ? integer(because, "frame") : 0,
          because.is_object() ? integer(because, "object") : 0};
}

Json BudgetFrameRecord::toJson() const {
  Json json = {{"frame", frame},
               {"pixels_cut", pixelsCut},
               {"largest_loss", measuredJson(largestLoss)},
               {"summed_loss", measuredJson(summedLoss)},
               {"largest_relative_loss", measuredJson(largestRelativeLoss)},
               {"popping_score", measuredJson(poppingScore)}};
  if (lights) json["lights"] = lightsJson(*lights);
  return json;
}

BudgetFrameRecord BudgetFrameRecord::fromJson(const Json& json) {
  BudgetFrameRecord f;
  f.frame = integer(json, "frame");
  f.pixelsCut = integer(json, "pixels_cut");
  f.largestLoss = measured(json, "largest_loss");
  f.summedLoss = measured(json, "summed_loss");
  f.largestRelativeLoss = measured(json, "largest_relative_loss");
  f.poppingScore = measured(json, "popping_score");
  if (json.contains("lights")) f.lights = objects<BudgetLightRecord>(json, "lights", BudgetLightRecord::fromJson);
  return f;
}

Json SceneBudgetRecord::toJson() const {
  if (!error.empty()) return {{"error", error}};
  Json frameList = Json::array();
  for (const BudgetFrameRecord& f : frames) frameList.push_back(f.toJson());
  if (!cuts) return {{"cuts", false}, {"frames", frameList}};
  Json images = {{"reach", reachImage}, {"kept", keptImage}, {"loss", lossImage}};
  if (!keptStripImage.empty()) images["kept_strip"] = keptStripImage;
  return {{"cuts", true},
          {"frames", frameList},
          {"maps_frame", mapsFrame},
          {"images", images},
          {"lights_not_kept", lightsJson(lightsNotKept)}};
}

SceneBudgetRecord SceneBudgetRecord::fromJson(const std::string& scene, const Json& json) {
  SceneBudgetRecord b;
  b.scene = scene;
  if (!json.is_object()) {
    b.error = "not an object in results.json";
    return b;
  }
  b.error = text(json, "error");
  b.cuts = boolean(json, "cuts");
  b.frames = objects<BudgetFrameRecord>(json, "frames", BudgetFrameRecord::fromJson);
  b.mapsFrame = integer(json, "maps_frame");
  if (const Json images = carried(json, "images"); images.is_object()) {
    b.reachImage = text(images, "reach");
    b.keptImage = text(images, "kept");
    b.lossImage = text(images, "loss");
    b.keptStripImage = text(images, "kept_strip");
  }
  b.lightsNotKept = objects<BudgetLightRecord>(json, "lights_not_kept", BudgetLightRecord::fromJson);
  return b;
}

Json budgetsJson(const std::vector<SceneBudgetRecord>& budgets) {
  Json json = Json::object();
  for (const SceneBudgetRecord& b : budgets) json[b.scene] = b.toJson();
  return json;
}

std::vector<SceneBudgetRecord> budgetsFromJson(const Json& json) {
  std::vector<SceneBudgetRecord> budgets;
  if (!json.is_object()) return budgets;
  for (const auto& [scene, value] : json.items()) budgets.push_back(SceneBudgetRecord::fromJson(scene, value));
  return budgets;
}

}  // namespace results
