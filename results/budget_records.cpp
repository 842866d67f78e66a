#include "results/budget_records.h"

#include "results/json_fields.h"

namespace results {
namespace {

using namespace fields;

// A frame's numbers, in budget.json's order.
constexpr std::pair<long long BudgetFrameRecord::*, const char*> kFrameCounts[] = {
    {&BudgetFrameRecord::frame, "frame"}, {&BudgetFrameRecord::pixelsCut, "pixels_cut"}};
constexpr std::pair<Measured BudgetFrameRecord::*, const char*> kFrameLosses[] = {
    {&BudgetFrameRecord::largestLoss, "largest_loss"}, {&BudgetFrameRecord::summedLoss, "summed_loss"},
    {&BudgetFrameRecord::largestRelativeLoss, "largest_relative_loss"},
    {&BudgetFrameRecord::poppingScore, "popping_score"}};
// A light's pixel counts before why it is not kept.
constexpr std::pair<long long BudgetLightRecord::*, const char*> kLightCounts[] = {
    {&BudgetLightRecord::reachPixels, "reach_pixels"}, {&BudgetLightRecord::keptPixels, "kept_pixels"},
    {&BudgetLightRecord::vertexPixels, "vertex_pixels"}, {&BudgetLightRecord::notKeptPixels, "not_kept_pixels"}};

}  // namespace

Json BudgetLightRecord::toJson() const {
  Json json = {{"light", light}, {"name", name}};
  for (const auto& [field, key] : kLightCounts) json[key] = this->*field;
  json["not_kept_because"] = {{"frame", cutByFrame}, {"object", cutByObject}};
  return json;
}

BudgetLightRecord BudgetLightRecord::fromJson(const Json& json) {
  BudgetLightRecord l;
  l.light = integer(json, "light");
  l.name = text(json, "name");
  for (const auto& [field, key] : kLightCounts) l.*field = integer(json, key);
  if (const Json because = carried(json, "not_kept_because"); because.is_object()) {
    l.cutByFrame = integer(because, "frame");
    l.cutByObject = integer(because, "object");
  }
  return l;
}

Json BudgetFrameRecord::toJson() const {
  Json json = Json::object();
  for (const auto& [field, key] : kFrameCounts) json[key] = this->*field;
  for (const auto& [field, key] : kFrameLosses) json[key] = measuredJson(this->*field);
  if (lights) json["lights"] = arrayOf(*lights);
  return json;
}

BudgetFrameRecord BudgetFrameRecord::fromJson(const Json& json) {
  BudgetFrameRecord f;
  for (const auto& [field, key] : kFrameCounts) f.*field = integer(json, key);
  for (const auto& [field, key] : kFrameLosses) f.*field = measured(json, key);
  if (json.contains("lights")) f.lights = objects<BudgetLightRecord>(json, "lights", BudgetLightRecord::fromJson);
  return f;
}

Json SceneBudgetRecord::toJson() const {
  if (!error.empty()) return {{"error", error}};
  const Json frameList = arrayOf(frames);
  if (!cuts) return {{"cuts", false}, {"frames", frameList}};
  Json images = {{"reach", reachImage}, {"kept", keptImage}, {"loss", lossImage}};
  if (!keptStripImage.empty()) images["kept_strip"] = keptStripImage;
  return {{"cuts", true},
          {"frames", frameList},
          {"maps_frame", mapsFrame},
          {"images", images},
          {"lights_not_kept", arrayOf(lightsNotKept)}};
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
