// The 1280x720 64-light field in every mode: frame, frame_readback (the
// light-path modes, not on a slow driver), pipeline. Error counters against the ideal reference of the
// field (one per profile, BRDF and light set: all-lights, per-object and
// full-shader share one).
#include "baking/bake.h"
#include "suite/bench/bench_families.h"
#include "suite/bench/bench_scenes.h"

#include <algorithm>
#include <iterator>
#include <utility>

namespace bench {
namespace {

using namespace lighting;

// The specular modes (SPEC 9, "the specular BRDF against Lambert"): the same
// field and lights with every object srp, forward with all lights and with
// per-object lists, each specialised and with the full shader; their error
// is against the ideal reference of the srp field. The Lambert modes of the
// same name without "srp-brdf" are what they cost against.
const char* const kSpecularSuffix = "srp-brdf";

FieldModeSpec modeOf(FrameMode scene, bool fullShader, std::string name, bool specularBrdf = false) {
  FieldModeSpec mode;
  mode.name = std::move(name);
  mode.field.mode = scene;
  mode.field.specularBrdf = specularBrdf;
  mode.fullShader = fullShader;
  return mode;
}

// The ideal reference a mode's error is against: one per profile, BRDF and
// light set (all-lights, per-object and full-shader share one; the deferred
// modes take the forward field's, fieldModes).
std::string referenceKeyOf(const std::string& scene, const FieldModeSpec& mode) {
  std::string key = scene + (mode.field.mode == FrameMode::Legacy4x4 ? "/legacy" : "/srp");
  if (mode.field.specularBrdf) key.append("-").append(kSpecularSuffix);
  if (mode.field.cookies) key.append("-").append(kCookiesMode);
  else if (mode.field.shadows) key.append("-shadows");  // every resolution and filter: ray-traced shadows
  else if (mode.field.shadowLights) key.append("-").append(kShadowLightsMode);
  else if (mode.field.cookieLights) key.append("-").append(kCookieLightsMode);
  return key;
}

// The light paths as shipped: forward all-lights, per-object and legacy,
// deferred in each light buffer. frame_readback times these only: a
// readback costs the same 1280x720 image whatever the mode drew, so in the
// other modes it would repeat their frame time plus that constant; and they
// are the whole set on a second context path to a driver.
bool isLightPathMode(const std::string& mode) {
  for (const FrameMode m : {FrameMode::AllLights, FrameMode::PerObject, FrameMode::Legacy4x4, FrameMode::DeferredHdr32,
                            FrameMode::DeferredHdr16, FrameMode::DeferredLdr8, FrameMode::Clustered})
    if (mode == modeName(m)) return true;
  return false;
}

}  // namespace

// A slow driver (by measured speed, driver_speed.h) draws the field at
// 160x90 in its full set too: the full bench's budget has no room for its
// feature frames at a larger size. Its error is still measured on every
// mode; its speed is a reference rasterizer's.
FieldSize fieldSize(const RunState& run) {
  if (run.settings.fieldWidth > 0) return {run.settings.fieldWidth, run.settings.fieldHeight};
  if (run.slow()) return {160, 90};
  if (run.settings.quick) return {320, 180};
  return {1280, 720};
}

std::string fieldSceneName(const RunState& run) {
  const FieldSize size = fieldSize(run);
  return "lights64-" + std::to_string(size.width) + "x" + std::to_string(size.height);
}

std::string shadowModeName(ShadowFilter filter, int resolution) {
  const char* name = filter == ShadowFilter::Hard ? "hard" : filter == ShadowFilter::Bilinear ? "bilinear" : "tent3x3";
  std::string mode = "shadows-";
  mode += name;
  mode += '-';
  mode += std::to_string(resolution);
  return mode;
}

// The modes of the speed-against-error plot: each profile and light path as
// shipped (specialised shader), and with the full shader, which shows what
// specialization buys; the deferred path in each light buffer (SPEC 3.7),
// whose error against the same ideal reference as all-lights is what the
// buffer's format costs; cookies on and off (SPEC 3.10 and 9): `cookies`
// against `cookie-lights`, the same lights without their cookies, so the
// pair differs by what sampling the cookies costs, each against the ideal
// reference of its own scene. A slow driver skips the slowest, full-shader
// all-lights (some 30 s a frame), and still has the rest.
std::vector<FieldModeSpec> fieldModeSpecs(bool quick, bool slow, bool lightPathsOnly) {
  std::vector<FieldModeSpec> modes = {modeOf(FrameMode::AllLights, false, modeName(FrameMode::AllLights)),
                                      modeOf(FrameMode::PerObject, false, modeName(FrameMode::PerObject)),
                                      modeOf(FrameMode::Legacy4x4, false, modeName(FrameMode::Legacy4x4)),
                                      modeOf(FrameMode::PerObject, true, modeName(FrameMode::PerObject) + "-full-shader"),
                                      modeOf(FrameMode::Legacy4x4, true, modeName(FrameMode::Legacy4x4) + "-full-shader")};
  if (!slow) modes.insert(modes.begin() + 3, modeOf(FrameMode::AllLights, true, "full-shader"));
  if (quick) modes.resize(2);
  // Forward+: every kept light, each pixel over its cluster's.
  modes.insert(modes.begin() + 2, modeOf(FrameMode::Clustered, false, modeName(FrameMode::Clustered)));
  const std::string specular = kSpecularSuffix;
  modes.push_back(modeOf(FrameMode::AllLights, false, specular, true));
  if (!quick) {
    modes.push_back(modeOf(FrameMode::PerObject, false, modeName(FrameMode::PerObject) + "-" + specular, true));
    if (!slow) modes.push_back(modeOf(FrameMode::AllLights, true, specular + "-full-shader", true));
    modes.push_back(
        modeOf(FrameMode::PerObject, true, modeName(FrameMode::PerObject) + "-" + specular + "-full-shader", true));
  }
  // Cookies on and off: the pair in the full set (bench.cookie-smoke runs it
  // filtered); --quick leaves it out, a cookie frame being among the
  // slowest of every driver.
  if (!quick) {
    modes.push_back(modeOf(FrameMode::AllLights, false, kCookieLightsMode));
    modes.back().field.cookieLights = true;
    modes.push_back(modeOf(FrameMode::AllLights, false, kCookiesMode));
    modes.back().field.cookies = true;
  }
  // Shadow maps at 256 to 4096 texels with each filter (SPEC 3.9 and 9;
  // kShadowResolutions, kFilteredShadowResolutions), each against ray-traced
  // shadows (--ideal), and the same lights casting nothing: the full set
  // only (bench.shadow-smoke runs one of them filtered), as for the cookies.
  if (!quick) {
    modes.push_back(modeOf(FrameMode::AllLights, false, kShadowLightsMode));
    modes.back().field.shadowLights = true;
    for (const ShadowFilter filter : {ShadowFilter::Hard, ShadowFilter::Bilinear, ShadowFilter::Tent3x3})
      for (const int resolution : kShadowResolutions) {
        if (filter != ShadowFilter::Hard && std::ranges::find(kFilteredShadowResolutions, resolution) ==
                                                std::end(kFilteredShadowResolutions))
          continue;
        // A slow driver (its share of the budget): one mode, bilinear at
        // 256, a shadowed frame being slow even at 320x180.
        if (slow && (resolution != 256 || filter != ShadowFilter::Bilinear)) continue;
        modes.push_back(modeOf(FrameMode::AllLights, false, shadowModeName(filter, resolution)));
        modes.back().field.shadows = true;
        modes.back().field.shadowResolution = resolution;
        modes.back().field.shadowFilter = filter;
      }
  }
  for (const FrameMode deferred : {FrameMode::DeferredHdr32, FrameMode::DeferredHdr16, FrameMode::DeferredLdr8})
    modes.push_back(modeOf(deferred, false, modeName(deferred)));
  if (lightPathsOnly)
    std::erase_if(modes, [](const FieldModeSpec& mode) { return mode.fullShader || !isLightPathMode(mode.name); });
  return modes;
}

std::string denseFieldSceneName(const RunState& run) {
  const FieldSize size = fieldSize(run);
  return "dense64-" + std::to_string(size.width) + "x" + std::to_string(size.height);
}

// The dense field (kDenseFieldRangeScale): the three ways to light
// every kept light per pixel or some of them, each against the dense field's
// own ideal: all-lights, per-object (truncated at 8 of 23 or more) and clustered.
NamedFrames denseFieldModes(const RunState& run) {
  const std::string scene = denseFieldSceneName(run);
  const FieldSize size = fieldSize(run);
  NamedFrames frames;
  for (const FrameMode mode : {FrameMode::AllLights, FrameMode::PerObject, FrameMode::Clustered}) {
    frames.emplace_back(modeName(mode), lazyBenchFrame(true, [grid = run.settings.clusterGrid, scene, size, mode] {
      FieldSpec field;
      field.width = size.width;
      field.height = size.height;
      field.mode = mode;
      field.rangeScale = kDenseFieldRangeScale;
      BenchFrameSpec spec;
      spec.prepared = prepareScene(fieldScene(field, scene + "-" + modeName(mode)));
      spec.referenceKey = scene + "/srp";
      spec.errorKey = scene + "/" + modeName(mode);
      spec.everyLightInView = true;
      if (mode == FrameMode::Clustered) spec.clusters = grid;
      if (mode == FrameMode::PerObject) spec.leastObjectLights = kDenseFieldLeastObjectLights;
      return makeBenchFrame(std::move(spec));
    }));
  }
  return frames;
}

void registerDenseFieldModes(Registrar& r, const NamedFrames& frames) {
  const std::string scene = denseFieldSceneName(r.run());
  for (const auto& [mode, bench] : frames) r.frame(scene, mode, "", bench, false);
}

FieldModes fieldModes(const RunState& run) {
  const std::string scene = fieldSceneName(run);
  const FieldSize size = fieldSize(run);
  FieldModes frames;
  bool shadowPipelineTimed = false;
  for (FieldModeSpec mode : fieldModeSpecs(run.settings.quick, run.slow(), run.secondContextPath())) {
    mode.field.width = size.width;
    mode.field.height = size.height;
    const FieldSpec& field = mode.field;
    const std::string referenceKey = referenceKeyOf(scene, mode);
    LazyFrame bench = lazyBenchFrame(!referenceKey.empty(), [grid = run.settings.clusterGrid, scene, mode, referenceKey] {
      const FieldSpec& field = mode.field;
      BenchFrameSpec spec;
      spec.prepared = baking::prepareBakedScene(fieldScene(field, scene + "-" + mode.name));
      spec.fullShader = mode.fullShader;
      spec.referenceKey = referenceKey;
      spec.errorKey = scene + "/" + mode.name;
      spec.everyLightInView = true;
      if (field.mode == FrameMode::Clustered) spec.clusters = grid;
      if (deferredBufferOf(field.mode)) {
        // The deferred modes share the srp reference of the forward field, made
        // from that scene whichever mode runs first: a deferred scene's own
        // reference includes its buffer's saturation (ldr8), which is part of
        // the error a buffer costs.
        FieldSpec forward = field;
        forward.mode = FrameMode::AllLights;
        spec.referencePrepared = prepareScene(fieldScene(forward, scene + "-forward-reference"));
      }
      return makeBenchFrame(std::move(spec));
    });
    (mode.fullShader ? frames.full : frames.shipped).emplace_back(mode.name, bench);
    // Pipelines: all-lights only on a slow driver, a second context path and
    // with --quick. Of the shadow modes the first only: a map's size and
    // filter are no shader constants (shaders/shader_constants.h), so the
    // eleven compile the same pipeline.
    const bool samePipelineTimed = field.shadows && std::exchange(shadowPipelineTimed, true);
    if (mode.name == modeName(FrameMode::AllLights) ||
        !(run.slow() || run.settings.quick || run.secondContextPath() || samePipelineTimed))
      frames.pipeline.emplace_back(mode.name, bench);
  }
  return frames;
}

void registerFieldModes(Registrar& r, const NamedFrames& frames) {
  const std::string scene = fieldSceneName(r.run());
  for (const auto& [mode, bench] : frames) {
    r.frame(scene, mode, "", bench, false);
    if (!r.run().slow() && isLightPathMode(mode)) r.frame(scene, mode, "", bench, true);
  }
}

void registerFieldPipelines(Registrar& r, const NamedFrames& frames) {
  const std::string scene = fieldSceneName(r.run());
  for (const auto& [mode, bench] : frames) r.pipeline(scene, mode, bench);
}

}  // namespace bench
