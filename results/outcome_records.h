// What a task's comparison came to, typed (docs/results-format.md, a test's
// "metrics", "frames", "timings_ms" and "evidence"): the worker fills them,
// results.json carries them, the reports read them. Each record's keys are
// spelled once, in its toJson and fromJson.
#pragma once

#include "comparison/verdict.h"

#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace results {

using Json = nlohmann::ordered_json;

// Where a task's time went, in milliseconds (results.json "timings_ms"): the
// worker's stages, then their total.
struct StageTimes {
  double reference = 0;
  double pipeline = 0;
  double draw = 0;
  double readback = 0;
  double compare = 0;
  double total = 0;

  // Every field with its key, in results.json's order: the one spelling of
  // the stage names, which the writer, the reader and the reports' table use.
  static constexpr std::array<std::pair<double StageTimes::*, const char*>, 6> kFields = {{
      {&StageTimes::reference, "reference"},
      {&StageTimes::pipeline, "pipeline"},
      {&StageTimes::draw, "draw"},
      {&StageTimes::readback, "readback"},
      {&StageTimes::compare, "compare"},
      {&StageTimes::total, "total"},
  }};
  Json toJson() const;
  // null (a task that never reported times) or anything but an object:
  // nullopt; a stage that is missing or no number reads as 0.
  static std::optional<StageTimes> fromJson(const Json& json);
};

// A value that is not finite is written as null (JSON has neither NaN nor
// infinity): nullopt here.
using Measured = std::optional<double>;
inline Measured measuredOf(double value) { return std::isfinite(value) ? Measured(value) : std::nullopt; }

// One of the worst pixels of the evidence frame, with what the reference
// allows there: reference +- tolerance * toleranceScale per channel.
struct WorstPixel {
  long long x = 0;
  long long y = 0;
  std::array<Measured, 3> result;
  std::array<Measured, 3> reference;
  std::array<Measured, 3> tolerance;
  double toleranceScale = 1;

  Json toJson() const;
  static WorstPixel fromJson(const Json& json);
};

// `run --sharpness` on a model test: the smallest relative brightness error,
// each way, that its comparison catches (nullopt: none up to twice as bright).
struct CaughtBrightness {
  Measured brighter;
  Measured darker;
};

// Over every frame checked: counts summed, errors and tightness the largest;
// the worst pixels are the evidence frame's.
struct Metrics {
  long long comparedPixels = 0;
  long long maskedPixels = 0;
  long long litComparedPixels = 0;  // compared, and above the flush-to-zero floor in the reference
  long long failingPixels = 0;
  long long nonFinitePixels = 0;
  long long maxFailingPixels = 0;
  Measured maxAbsError = 0.0;
  Measured rmse = 0.0;
  Measured tightness = 0.0;  // largest |error| / tolerance
  bool tightnessIsInfinite = false;  // an error where the tolerance is 0
  bool expectFail = false;
  std::vector<WorstPixel> worst;
  std::optional<CaughtBrightness> caught;

  Json toJson() const;
  static Metrics fromJson(const Json& json);
};

// One frame of a test.
struct FrameRecord {
  long long frame = 0;
  comparison::Verdict verdict = comparison::Verdict::Fail;  // Pass or Fail; a word it is not reads as Fail
  long long failingPixels = 0;
  Measured maxAbsError;
  Measured tightness;
  Measured idealError;   // against the --ideal reference (animated scenes)
  Measured poppingJump;  // SPEC 6, from the second frame on

  Json toJson() const;
  static FrameRecord fromJson(const Json& json);
};

// Where a failure's evidence is, relative to the run folder. A failure past
// --evidence-limit keeps only its numbers (summaryJson, imagesKept false).
struct EvidenceRecord {
  long long frame = 0;
  std::string resultPng;
  std::string referencePng;
  std::string errorMaskPng;
  std::string viewer;
  std::string summaryJson;
  bool imagesKept = true;
  std::string test;  // a mutant's evidence: the test that killed it; "" otherwise

  // The evidence a worker writes into `dir` (evidence/<test>, mutants/<mutant>.<backend>).
  static EvidenceRecord inFolder(const std::string& dir, long long frame);
  Json toJson() const;
  static EvidenceRecord fromJson(const Json& json);
};

// What a task's comparison came to, as a worker reports it and as a test's
// record keeps it. Everything but the message is absent for a Crash, a
// Timeout, a NotSupported and a NotRun.
struct TaskOutcome {
  std::string message;
  std::optional<Metrics> metrics;
  std::optional<std::vector<FrameRecord>> frames;
  Measured poppingScore;  // animated scenes: the largest popping jump
  std::optional<StageTimes> timingsMs;
  std::optional<EvidenceRecord> evidence;
};

// The outcome's keys, after whatever comes before them in a record.
void writeOutcome(const TaskOutcome& outcome, Json& json);
void readOutcome(const Json& json, TaskOutcome& outcome);

}  // namespace results
