#include "results/outcome_records.h"

#include "results/json_fields.h"

namespace results {
namespace {

using namespace fields;

Json channels(const std::array<Measured, 3>& values) {
  return Json::array({measuredJson(values[0]), measuredJson(values[1]), measuredJson(values[2])});
}

std::array<Measured, 3> channelsAt(const Json& json, const char* key) {
  std::array<Measured, 3> values;
  const auto it = json.find(key);
  if (it == json.end() || !it->is_array()) return values;
  for (std::size_t c = 0; c < 3 && c < it->size(); ++c) values[c] = measured((*it)[c]);
  return values;
}

// Metrics' counts, then its measured errors, in results.json's order.
constexpr std::pair<long long Metrics::*, const char*> kMetricCounts[] = {
    {&Metrics::comparedPixels, "compared_pixels"}, {&Metrics::maskedPixels, "masked_pixels"},
    {&Metrics::litComparedPixels, "lit_compared_pixels"}, {&Metrics::failingPixels, "failing_pixels"},
    {&Metrics::nonFinitePixels, "non_finite_pixels"}, {&Metrics::maxFailingPixels, "max_failing_pixels"}};
constexpr std::pair<Measured Metrics::*, const char*> kMetricErrors[] = {
    {&Metrics::maxAbsError, "max_abs_error"}, {&Metrics::rmse, "rmse"}, {&Metrics::tightness, "tightness"}};
// A frame's errors after its failing pixels.
constexpr std::pair<Measured FrameRecord::*, const char*> kFrameErrors[] = {
    {&FrameRecord::maxAbsError, "max_abs_error"}, {&FrameRecord::tightness, "tightness"},
    {&FrameRecord::idealError, "ideal_error"}, {&FrameRecord::poppingJump, "popping_jump"}};
// Evidence's files, in results.json's order.
constexpr std::pair<std::string EvidenceRecord::*, const char*> kEvidenceFiles[] = {
    {&EvidenceRecord::resultPng, "result_png"}, {&EvidenceRecord::referencePng, "reference_png"},
    {&EvidenceRecord::errorMaskPng, "error_mask_png"}, {&EvidenceRecord::viewer, "viewer"},
    {&EvidenceRecord::summaryJson, "summary_json"}};

}  // namespace

Json StageTimes::toJson() const {
  Json json = Json::object();
  for (const auto& [field, key] : kFields) json[key] = this->*field;
  return json;
}

std::optional<StageTimes> StageTimes::fromJson(const Json& json) {
  if (!json.is_object()) return std::nullopt;
  StageTimes times;
  for (const auto& [field, key] : kFields) times.*field = number(json, key);
  return times;
}

Json WorstPixel::toJson() const {
  return {{"x", x},
          {"y", y},
          {"result", channels(result)},
          {"reference", channels(reference)},
          {"tolerance", channels(tolerance)},
          {"tolerance_scale", toleranceScale}};
}

WorstPixel WorstPixel::fromJson(const Json& json) {
  WorstPixel p;
  p.x = integer(json, "x");
  p.y = integer(json, "y");
  p.result = channelsAt(json, "result");
  p.reference = channelsAt(json, "reference");
  p.tolerance = channelsAt(json, "tolerance");
  p.toleranceScale = measured(json, "tolerance_scale").value_or(1.0);
  return p;
}

Json Metrics::toJson() const {
  Json json = Json::object();
  for (const auto& [field, key] : kMetricCounts) json[key] = this->*field;
  for (const auto& [field, key] : kMetricErrors) json[key] = measuredJson(this->*field);
  json["tightness_is_infinite"] = tightnessIsInfinite;
  json["expect_fail"] = expectFail;
  json["worst"] = arrayOf(worst);
  if (caught) {
    json["smallest_caught_brighter"] = measuredJson(caught->brighter);
    json["smallest_caught_darker"] = measuredJson(caught->darker);
  }
  return json;
}

Metrics Metrics::fromJson(const Json& json) {
  Metrics m;
  for (const auto& [field, key] : kMetricCounts) m.*field = integer(json, key);
  for (const auto& [field, key] : kMetricErrors) m.*field = measured(json, key);
  m.tightnessIsInfinite = boolean(json, "tightness_is_infinite");
  m.expectFail = boolean(json, "expect_fail");
  m.worst = objects<WorstPixel>(json, "worst", WorstPixel::fromJson);
  if (json.contains("smallest_caught_brighter") || json.contains("smallest_caught_darker"))
    m.caught = CaughtBrightness{measured(json, "smallest_caught_brighter"), measured(json, "smallest_caught_darker")};
  return m;
}

Json FrameRecord::toJson() const {
  Json json = {{"frame", frame}, {"verdict", comparison::verdictName(verdict)}, {"failing_pixels", failingPixels}};
  for (const auto& [field, key] : kFrameErrors) json[key] = measuredJson(this->*field);
  return json;
}

FrameRecord FrameRecord::fromJson(const Json& json) {
  FrameRecord f;
  f.frame = integer(json, "frame");
  f.verdict = comparison::parseVerdict(text(json, "verdict")).value_or(comparison::Verdict::Fail);
  f.failingPixels = integer(json, "failing_pixels");
  for (const auto& [field, key] : kFrameErrors) f.*field = measured(json, key);
  return f;
}

EvidenceRecord EvidenceRecord::inFolder(const std::string& dir, long long frame) {
  EvidenceRecord e;
  e.frame = frame;
  e.resultPng = dir + "/result.png";
  e.referencePng = dir + "/reference.png";
  e.errorMaskPng = dir + "/error-mask.png";
  e.viewer = dir + "/viewer.html";
  e.summaryJson = dir + "/summary.json";
  return e;
}

Json EvidenceRecord::toJson() const {
  Json json = {{"frame", frame}};
  if (imagesKept) {
    for (const auto& [field, key] : kEvidenceFiles) json[key] = this->*field;
  } else {
    json["summary_json"] = summaryJson;
    json["images_kept"] = false;
  }
  if (!test.empty()) json["test"] = test;
  return json;
}

EvidenceRecord EvidenceRecord::fromJson(const Json& json) {
  EvidenceRecord e;
  e.frame = integer(json, "frame");
  for (const auto& [field, key] : kEvidenceFiles) e.*field = text(json, key);
  // Only a boolean false says the images went (results.json is not trusted).
  const auto kept = json.find("images_kept");
  e.imagesKept = !(kept != json.end() && kept->is_boolean() && !kept->get<bool>());
  e.test = text(json, "test");
  return e;
}

void writeOutcome(const TaskOutcome& outcome, Json& json) {
  json["message"] = outcome.message;
  json["metrics"] = outcome.metrics ? outcome.metrics->toJson() : Json(nullptr);
  json["frames"] = outcome.frames ? arrayOf(*outcome.frames) : Json(nullptr);
  json["popping_score"] = measuredJson(outcome.poppingScore);
  json["timings_ms"] = outcome.timingsMs ? outcome.timingsMs->toJson() : Json(nullptr);
  json["evidence"] = outcome.evidence ? outcome.evidence->toJson() : Json(nullptr);
}

void readOutcome(const Json& json, TaskOutcome& outcome) {
  outcome.message = text(json, "message");
  if (const Json m = carried(json, "metrics"); m.is_object()) outcome.metrics = Metrics::fromJson(m);
  if (const Json f = carried(json, "frames"); f.is_array()) outcome.frames = objects<FrameRecord>(json, "frames", FrameRecord::fromJson);
  outcome.poppingScore = measured(json, "popping_score");
  outcome.timingsMs = StageTimes::fromJson(carried(json, "timings_ms"));
  if (const Json e = carried(json, "evidence"); e.is_object()) outcome.evidence = EvidenceRecord::fromJson(e);
}

}  // namespace results
