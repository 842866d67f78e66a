#include "conformance/scene_check.h"

#include "lighting/light_clusters.h"

#include "conformance/cpu_mutants.h"
#include "conformance/popping.h"
#include "conformance/reference_cache.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <type_traits>

namespace conformance {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// Runs `work` and adds its wall time to `total`.
template <typename Work>
auto timed(double& total, Work&& work) {
  const auto start = Clock::now();
  if constexpr (std::is_void_v<decltype(work())>) {
    work();
    total += millisecondsSince(start);
  } else {
    auto value = work();
    total += millisecondsSince(start);
    return value;
  }
}

}  // namespace

reference::ReferenceOptions referenceOptionsFor(const lighting::Scene& scene) {
  reference::ReferenceOptions options;
  options.bakedLightsRealtime = scene.expect.against == lighting::CompareAgainst::Realtime;
  // SPEC 3.9: the failing pixels' shadow intervals go into the evidence.
  for (const lighting::Light& light : scene.lights) options.keepShadowIntervals |= light.shadowMap.has_value();
  return options;
}

std::optional<ReferenceCaching> referenceCaching(const std::filesystem::path& directory,
                                                 const std::filesystem::path& sceneFile, const lighting::Scene& scene) {
  if (directory.empty()) return std::nullopt;
  return ReferenceCaching{directory, sceneContentDigest(sceneFile, scene)};
}

SceneReferences::SceneReferences(std::shared_ptr<const lighting::PreparedScene> prepared,
                                 std::optional<ReferenceCaching> caching)
    : prepared_(std::move(prepared)), caching_(std::move(caching)) {}

const reference::ReferenceRenderer& SceneReferences::renderer() {
  if (!renderer_) renderer_ = std::make_unique<reference::ReferenceRenderer>(prepared_);
  return *renderer_;
}

reference::ReferenceImages SceneReferences::render(int index, const reference::ReferenceOptions& options) {
  const lighting::Frame& f = frame(index);
  return timed(referenceMs_, [&] {
    if (!caching_ || !cacheable(options)) return renderer().render(f, options);
    bool hit = false;
    reference::ReferenceImages images =
        cachedReference(caching_->directory, referenceCacheKey(caching_->sceneDigest, index, options),
                        [&] { return renderer().render(f, options); }, &hit);
    cacheHits_ += hit ? 1 : 0;
    return images;
  });
}

const lighting::Frame& SceneReferences::frame(int index) {
  auto it = frames_.find(index);
  if (it == frames_.end()) it = frames_.emplace(index, lighting::prepareFrame(prepared_, index)).first;
  return it->second;
}

std::tuple<int, int, int> SceneReferences::referenceKey(int index, int subTexelBits, int subPixelBits) const {
  // A device that reports fewer bits than the minimum is held to the minimum
  // (SPEC 7: "2^-4 ... unless the device reports more"). A scene without a
  // filtered texture has one reference whatever the bits: the minimum's.
  const bool filtered = reference::readsFilteredTextures(*prepared_);
  const int bits = filtered ? std::max(subTexelBits, kMinimumSubTexelBits) : kMinimumSubTexelBits;
  const int snapBits = std::max(subPixelBits, reference::tolerance::kMinimumSubPixelBits);
  return {index, bits, snapBits};
}

reference::ReferenceOptions SceneReferences::optionsOf(const std::tuple<int, int, int>& key) const {
  reference::ReferenceOptions options = referenceOptionsFor(prepared_->scene);
  options.filterWeightPrecision = std::ldexp(1.0, -std::get<1>(key));
  options.subPixelPrecisionBits = std::get<2>(key);
  return options;
}

const reference::ReferenceImages& SceneReferences::reference(int index, int subTexelBits, int subPixelBits) {
  const auto key = referenceKey(index, subTexelBits, subPixelBits);
  auto it = references_.find(key);
  if (it == references_.end()) it = references_.emplace(key, render(index, optionsOf(key))).first;
  return it->second;
}

const imaging::Image& SceneReferences::lightPart(int index, int subTexelBits, int subPixelBits) {
  const auto key = referenceKey(index, subTexelBits, subPixelBits);
  auto it = lightParts_.find(key);
  if (it == lightParts_.end()) {
    reference::ReferenceOptions options = optionsOf(key);
    options.valueOnly = true;
    options.keepLightPart = true;
    it = lightParts_.emplace(key, std::move(render(index, options).lightPart)).first;
  }
  return it->second;
}

std::vector<imaging::Image> SceneReferences::shadowMapImages(int index, int subPixelBits) {
  const lighting::Frame& f = frame(index);
  const auto maps = renderer().shadowMaps(f, 0, subPixelBits);
  std::vector<imaging::Image> images;
  for (const auto* list : {&f.shadows.maps, &f.shadows.cubes})
    for (const lighting::ShadowProjection& projection : *list)
      for (int v = 0; v < int(projection.views.size()); ++v) images.push_back(maps[projection.light]->viewImage(v));
  return images;
}

const reference::ReferenceImages& SceneReferences::ideal(int index) {
  auto it = ideals_.find(index);
  if (it == ideals_.end()) {
    reference::ReferenceOptions options;
    options.ideal = true;
    it = ideals_.emplace(index, render(index, options)).first;
  }
  return it->second;
}

const FrameCheck& SceneCheck::evidence() const {
  for (const FrameCheck& f : frames)
    if (f.frame == evidenceFrame) return f;
  throw std::logic_error("SceneCheck: no frame checked");
}

SceneCheck checkScene(SceneReferences& references, backends::Backend& backend, const CheckOptions& options) {
  const lighting::Scene& scene = references.prepared()->scene;
  const int frameCount = scene.frames.count;
  const bool animated = frameCount > 1;
  int first = 0, last = frameCount - 1;
  if (options.onlyFrame) {
    if (*options.onlyFrame < 0 || *options.onlyFrame >= frameCount)
      throw std::out_of_range("checkScene: frame " + std::to_string(*options.onlyFrame) + " of a scene with " +
                              std::to_string(frameCount) + " frame(s)");
    first = last = *options.onlyFrame;
  }

  SceneCheck check;
  const auto start = Clock::now();
  const double referenceMsBefore = references.referenceMilliseconds();
  imaging::Image previousError;
  double worstTightness = -1;
  bool allPass = true;
  for (int f = first; f <= last; ++f) {
    const backends::DeviceInfo device = backend.device();
    const reference::ReferenceImages& ref =
        references.reference(f, device.subTexelPrecisionBits, device.subPixelPrecisionBits);
    lighting::Frame frame = cpuMutantFrame(references.frame(f), options.mutant);
    if (options.clustered) lighting::useLightClusters(frame, *options.clustered);
    if (f == first) timed(check.timings.pipeline, [&] { backend.preparePipeline(frame); });
    timed(check.timings.draw, [&] { backend.draw(frame); });
    imaging::Image result = timed(check.timings.readback, [&] { return backend.readback(); });

    FrameCheck frameCheck{f, {}, kNaN, kNaN};
    frameCheck.comparison = timed(check.timings.compare, [&] {
      return comparison::compareImages(result, ref, scene.expect, options.worstCount);
    });
    if (options.measureSharpness && !scene.expect.expectFail) {
      const CaughtScale caught = smallestCaughtScale(
          result, references.lightPart(f, device.subTexelPrecisionBits, device.subPixelPrecisionBits), ref,
          scene.expect);
      if (!check.caughtScale) check.caughtScale = caught;
      check.caughtScale->brighter = std::min(check.caughtScale->brighter, caught.brighter);
      check.caughtScale->darker = std::min(check.caughtScale->darker, caught.darker);
    }
    // Animated scenes: the popping score; shadow maps: their error against
    // ray-traced shadows (SPEC 3.9 --ideal), information beside the verdict.
    if (animated || frame.shadows.any()) {
      const reference::ReferenceImages& ideal = references.ideal(f);
      timed(check.timings.compare, [&] {
        imaging::Image error = idealError(result, ideal, frameCheck.idealError);
        if (animated && !previousError.pixels.empty()) frameCheck.poppingJump = poppingJump(previousError, error);
        if (animated) previousError = std::move(error);
      });
    }

    // Evidence: the first failing frame, else the tightest one.
    const bool pass = frameCheck.comparison.verdict != comparison::Verdict::Fail;
    if (pass && check.qualityWarning.empty() && !frameCheck.comparison.qualityWarning.empty())
      check.qualityWarning = (animated ? "frame " + std::to_string(f) + ": " : std::string()) +
                             frameCheck.comparison.qualityWarning;
    const double tightness = frameCheck.comparison.maxErrorOverTolerance;
    const bool keep = allPass && (!pass || tightness > worstTightness || check.frames.empty());
    if (keep && !pass && frame.shadows.any()) {
      check.evidenceShadowMaps.backend = backend.readShadowMaps();
      check.evidenceShadowMaps.reference = references.shadowMapImages(f, backend.device().subPixelPrecisionBits);
    }
    if (keep) {
      check.evidenceFrame = f;
      check.evidenceResult = std::move(result);
      check.evidenceReference = ref;
      worstTightness = tightness;
    }
    allPass = allPass && pass;
    check.frames.push_back(std::move(frameCheck));
  }

  if (!allPass) check.qualityWarning.clear();
  check.verdict = !allPass                         ? comparison::Verdict::Fail
                  : check.qualityWarning.empty() ? comparison::Verdict::Pass
                                                 : comparison::Verdict::QualityWarning;
  if (animated && !options.onlyFrame) {
    double score = 0;
    for (const FrameCheck& f : check.frames)
      if (!std::isnan(f.poppingJump)) score = std::max(score, f.poppingJump);
    check.poppingScore = score;
  }
  check.timings.reference = references.referenceMilliseconds() - referenceMsBefore;
  check.timings.total = millisecondsSince(start);
  return check;
}

}  // namespace conformance
