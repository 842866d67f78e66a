// The 1280x720 64-light field in every mode: frame, frame_readback (not on a
// slow driver), pipeline. Error counters against the ideal reference of the
// field (one per profile: all-lights, per-object and full-shader share one).
#include "baking/bake.h"
#include "suite/bench/bench_families.h"
#include "suite/bench/bench_scenes.h"

namespace bench {
namespace {

using namespace lighting;

// The modes of the speed-against-error plot: each profile and light path as
// shipped (specialised shader), and with the full shader, which shows what
// specialization buys; the deferred path in each light buffer (SPEC 3.7),
// whose error against the same ideal reference as all-lights is what the
// buffer's format costs. A slow driver skips the slowest, full-shader
// all-lights (some 30 s a frame), and still has eight.
struct ModeSpec {
  FrameMode scene;  // which field: all lights, per-object lists, legacy, deferred
  bool fullShader;
  std::string name;
  bool specularBrdf = false;  // the srp BRDF on every object (SPEC 3.8)
};

// The specular modes (SPEC 9, "the specular BRDF against Lambert"): the same
// field and lights with every object srp, forward with all lights and with
// per-object lists, each specialised and with the full shader; their error
// is against the ideal reference of the srp field. The Lambert modes of the
// same name without "srp-brdf" are what they cost against.
const char* const kSpecularSuffix = "srp-brdf";

std::vector<ModeSpec> modesOf(const RunState& run) {
  std::vector<ModeSpec> modes = {{FrameMode::AllLights, false, modeName(FrameMode::AllLights)},
                                 {FrameMode::PerObject, false, modeName(FrameMode::PerObject)},
                                 {FrameMode::Legacy4x4, false, modeName(FrameMode::Legacy4x4)},
                                 {FrameMode::PerObject, true, modeName(FrameMode::PerObject) + "-full-shader"},
                                 {FrameMode::Legacy4x4, true, modeName(FrameMode::Legacy4x4) + "-full-shader"}};
  if (!run.slow()) modes.insert(modes.begin() + 3, {FrameMode::AllLights, true, "full-shader"});
  if (run.settings.quick) modes.resize(2);
  const std::string specular = kSpecularSuffix;
  modes.push_back({FrameMode::AllLights, false, specular, true});
  if (!run.settings.quick) {
    modes.push_back({FrameMode::PerObject, false, modeName(FrameMode::PerObject) + "-" + specular, true});
    if (!run.slow()) modes.push_back({FrameMode::AllLights, true, specular + "-full-shader", true});
    modes.push_back({FrameMode::PerObject, true, modeName(FrameMode::PerObject) + "-" + specular + "-full-shader", true});
  }
  for (const FrameMode deferred : {FrameMode::DeferredHdr32, FrameMode::DeferredHdr16, FrameMode::DeferredLdr8})
    modes.push_back({deferred, false, modeName(deferred)});
  return modes;
}

}  // namespace

FieldModes fieldModes(const RunState& run) {
  const std::string scene = kFieldScene;
  FieldModes frames;
  for (const ModeSpec& mode : modesOf(run)) {
    FieldSpec field;
    field.mode = mode.scene;
    field.specularBrdf = mode.specularBrdf;
    BenchFrameSpec spec;
    spec.prepared = baking::prepareBakedScene(fieldScene(field, scene + "-" + mode.name));
    spec.fullShader = mode.fullShader;
    spec.referenceKey = scene + (mode.scene == FrameMode::Legacy4x4 ? "/legacy" : "/srp") +
                        (mode.specularBrdf ? "-" + std::string(kSpecularSuffix) : "");
    spec.errorKey = scene + "/" + mode.name;
    spec.everyLightInView = true;
    if (deferredBufferOf(mode.scene)) {
      // The deferred modes share the srp reference of the forward field, made
      // from that scene whichever mode runs first: a deferred scene's own
      // reference includes its buffer's saturation (ldr8), which is part of
      // the error a buffer costs.
      FieldSpec forward = field;
      forward.mode = FrameMode::AllLights;
      spec.referencePrepared = prepareScene(fieldScene(forward, scene + "-forward-reference"));
    }
    std::shared_ptr<const BenchFrame> bench = makeBenchFrame(std::move(spec));
    (mode.fullShader ? frames.full : frames.shipped).emplace_back(mode.name, bench);
    // Pipelines: all-lights only on a slow driver and with --quick.
    if (mode.name == modeName(FrameMode::AllLights) || !(run.slow() || run.settings.quick))
      frames.pipeline.emplace_back(mode.name, bench);
  }
  return frames;
}

void registerFieldModes(Registrar& r, const NamedFrames& frames) {
  for (const auto& [mode, bench] : frames) {
    r.frame(kFieldScene, mode, "", bench, false);
    if (!r.run().slow()) r.frame(kFieldScene, mode, "", bench, true);
  }
}

void registerFieldPipelines(Registrar& r, const NamedFrames& frames) {
  for (const auto& [mode, bench] : frames) r.pipeline(kFieldScene, mode, bench);
}

}  // namespace bench
