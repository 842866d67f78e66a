// One scene on one backend, every frame, against the reference (SPEC 7) and,
// for animated scenes, against the `--ideal` reference for the popping score
// (SPEC 6). `lightcts compare` and the workers of `lightcts run` both call
// checkScene, so a verdict means the same thing in ctest and in a report.
#pragma once

#include "conformance/brightness_sharpness.h"
#include "backends/backend.h"
#include "comparison/comparison_report.h"
#include "comparison/image_comparison.h"
#include "lighting/frame.h"
#include "lighting/light_clusters.h"
#include "reference/reference_renderer.h"
#include "shaders/shader_variant.h"

#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <tuple>
#include <vector>

namespace conformance {

// The options of the reference a scene is compared against: its
// `expect.against` (docs/scene-format.md) picks the model's reference or the
// one with baked lights in real time. `lightcts reference` applies the same rule.
reference::ReferenceOptions referenceOptionsFor(const lighting::Scene& scene);

// Where SceneReferences keeps its references between processes
// (reference_cache.h): the cache folder and the scene's content digest.
struct ReferenceCaching {
  std::filesystem::path directory;
  std::string sceneDigest;  // sceneContentDigest of the scene file
};

// The caching of `sceneFile`'s references in `directory` (its content digest
// taken now); none when `directory` is empty.
std::optional<ReferenceCaching> referenceCaching(const std::filesystem::path& directory,
                                                 const std::filesystem::path& sceneFile, const lighting::Scene& scene);

// The references of one scene, rendered on first use and kept: a worker that
// renders the model and then every mutant pays for each reference once; with
// `caching`, every worker of a run and every later run share them on disk.
class SceneReferences {
 public:
  explicit SceneReferences(std::shared_ptr<const lighting::PreparedScene> prepared,
                           std::optional<ReferenceCaching> caching = std::nullopt);
  const std::shared_ptr<const lighting::PreparedScene>& prepared() const { return prepared_; }
  const lighting::Frame& frame(int index);
  // With referenceOptionsFor(scene), SPEC 7's filter weights exact to
  // 2^-subTexelBits (the device's DeviceInfo::subTexelPrecisionBits) and
  // vertices snapped to 2^-subPixelBits (DeviceInfo::subPixelPrecisionBits);
  // 4 is the Vulkan minimum of both and `lightcts reference`'s.
  const reference::ReferenceImages& reference(int frame, int subTexelBits = kMinimumSubTexelBits,
                                              int subPixelBits = reference::tolerance::kMinimumSubPixelBits);
  static constexpr int kMinimumSubTexelBits = 4;
  // SPEC 6 --ideal, for the popping score; it keeps the lightmaps whatever
  // `expect.against` says, so the baked part cancels and only budgets remain.
  const reference::ReferenceImages& ideal(int frame);
  // What the lights add to each pixel of reference(frame, ...)
  // (ReferenceImages::lightPart): the sharpness's scale mutant scales it.
  const imaging::Image& lightPart(int frame, int subTexelBits, int subPixelBits);
  // Time spent on references so far: rendering them, or reading them from the cache.
  double referenceMilliseconds() const { return referenceMs_; }
  int cacheHits() const { return cacheHits_; }  // references read from the cache so far
  // SPEC 3.9's evidence: the reference's maps of `frame` for a device with
  // `subPixelBits` (as reference() builds them), one image per view in
  // lighting::shadowPassViews order (ReferenceShadowMap::viewImage).
  std::vector<imaging::Image> shadowMapImages(int frame, int subPixelBits = reference::tolerance::kMinimumSubPixelBits);

 private:
  // Built on first use: a worker whose references all come from the cache
  // never builds the scene's BVH.
  const reference::ReferenceRenderer& renderer();
  reference::ReferenceImages render(int frame, const reference::ReferenceOptions& options);
  // reference()'s cache key, bits raised to the minimum, and its options.
  std::tuple<int, int, int> referenceKey(int frame, int subTexelBits, int subPixelBits) const;
  reference::ReferenceOptions optionsOf(const std::tuple<int, int, int>& key) const;

  std::shared_ptr<const lighting::PreparedScene> prepared_;
  std::optional<ReferenceCaching> caching_;
  std::unique_ptr<reference::ReferenceRenderer> renderer_;
  std::map<int, lighting::Frame> frames_;
  std::map<std::tuple<int, int, int>, reference::ReferenceImages> references_;  // by frame, sub-texel and sub-pixel bits
  std::map<int, reference::ReferenceImages> ideals_;
  std::map<std::tuple<int, int, int>, imaging::Image> lightParts_;  // keyed as references_
  double referenceMs_ = 0;
  int cacheHits_ = 0;
};

// Wall-clock milliseconds per stage, summed over the frames checked.
struct StageTimings {
  double reference = 0;  // reference and ideal renders done for this check (0 when cached)
  double pipeline = 0;   // Backend::preparePipeline
  double draw = 0;       // Backend::draw (waits for the device)
  double readback = 0;   // Backend::readback
  double compare = 0;    // compareImages and the popping arithmetic
  double total = 0;
};

struct FrameCheck {
  int frame = 0;
  comparison::Comparison comparison;
  // Animated scenes and scenes with shadow maps (otherwise NaN; poppingJump
  // animated scenes only). idealError: max over compared
  // pixels and RGB of |backend - ideal|. poppingJump: SPEC 6's
  // max over pixels |e_f - e_(f-1)| with e = backend - ideal, over pixels
  // compared in both frames; NaN on frame 0.
  double idealError;
  double poppingJump;
};

struct SceneCheck {
  // Fail when a frame fails; else QualityWarning when a frame checks
  // nothing (its comparison's qualityWarning); else Pass.
  comparison::Verdict verdict = comparison::Verdict::Fail;
  // The first vacuous frame's reason ("frame F: ..." in an animated scene),
  // or "": what results.json, junit.xml and the report give as the message.
  std::string qualityWarning;
  std::vector<FrameCheck> frames;
  std::optional<double> poppingScore;  // animated scenes: max poppingJump over frames
  // The frame whose images are kept as evidence: the first failing frame,
  // else the one with the largest tightness.
  int evidenceFrame = 0;
  imaging::Image evidenceResult;
  reference::ReferenceImages evidenceReference;
  // SPEC 3.9, a failing frame with shadow maps only: the backend's maps read
  // back and the reference's (comparison::ShadowMapEvidence).
  comparison::ShadowMapEvidence evidenceShadowMaps;
  StageTimings timings;
  // With CheckOptions::measureSharpness, the smallest brightness error each
  // way any frame's comparison catches (brightness_sharpness.h); none for an
  // expect_fail scene.
  std::optional<CaughtScale> caughtScale;
  const FrameCheck& evidence() const;  // the FrameCheck of evidenceFrame
};

struct CheckOptions {
  std::optional<int> onlyFrame;  // check one frame; default every frame of the scene
  int worstCount = 10;           // worst pixels kept per frame
  // The backend's mutant: a CPU mutant (conformance/cpu_mutants.h) alters the
  // frame the backend draws; the reference always gets the model's frame.
  shaders::Mutant mutant = shaders::Mutant::None;
  // The clustered benchmark mode (lighting/light_clusters.h): the
  // backend draws each frame over its clusters' lights, against the same
  // reference and tolerance (the mode drops no light that reaches a pixel).
  // useLightClusters throws std::invalid_argument for a scene it cannot draw.
  std::optional<lighting::ClusterGridSpec> clustered;
  // Bisect, per frame, the smallest brightness error the comparison catches
  // (SceneCheck::caughtScale): the suite's sharpness (`run --sharpness`).
  bool measureSharpness = false;
};

// Throws what the backend throws (NotSupportedError, DriverError).
SceneCheck checkScene(SceneReferences& references, backends::Backend& backend, const CheckOptions& options = {});

}  // namespace conformance
