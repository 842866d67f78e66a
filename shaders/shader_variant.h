// Which variant of the one set of shaders a backend builds. The shipped model
// is `specialised` with no mutant: features a frame does not use are switched
// off by specialization constants (shaders/lighting.glsl). The full shader and
// the mutants exist for tests only.
#pragma once

#include "lighting/deferred_lights.h"
#include "lighting/raster_state.h"
#include "shaders/shader_interface.h"  // generated from shaders/shader_interface.def

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace shaders {

// The mutants (SPEC 7): shaders::Mutant, their names and kinds, one line
// each in shaders/shader_interface.def.
const std::vector<MutantName>& mutantNames();
std::optional<Mutant> mutantFromName(std::string_view name);
std::string_view mutantName(Mutant mutant);

// The admissible variants (SPEC 7): shaders::Admissible, their names, what
// each does, where it is realised and the sentence that allows it, one line
// each in shaders/shader_interface.def.
const std::vector<AdmissibleName>& admissibleNames();
std::optional<Admissible> admissibleFromName(std::string_view name);
std::string_view admissibleName(Admissible variant);
const AdmissibleName& admissibleEntry(Admissible variant);  // variant != None
// Whether `variant` is realised on the backend `api` ("vulkan", "gl-egl",
// "gl-osmesa"): AdmissibleApis::Vulkan only there, None nowhere.
bool admissibleRealisedOn(Admissible variant, std::string_view api);

struct ShaderVariant {
  bool specialised = true;  // false: every feature on, whatever the frame uses
  Mutant mutant = Mutant::None;
  Admissible admissible = Admissible::None;
  // false (a driver probe, never the model's default: render_bench
  // --uniform_reads=constant): the uniforms that steer loops and branches
  // are read at constant offsets, which lavapipe 22.3 inlines and recompiles
  // for (shaders/light_data.glsl, opaque(); docs/vendors.md). The image is
  // the same either way.
  bool opaqueUniformReads = true;
};

// The rule the light pass draws volumes by under `mutant`: the model's, or
// point-volume-outside-only's (a pipeline mutant).
lighting::VolumeRule volumeRule(Mutant mutant);

// The light volumes of a deferred frame in the order its light pass blends
// them: lighting::lightVolumes's, last to first under the lights-reversed
// admissible variant (blending adds in draw order).
std::vector<lighting::LightVolume> lightVolumesInBlendOrder(const lighting::Frame& frame, const ShaderVariant& variant);

// The compare the shadow samplers use under `mutant`: the model's
// (lighting::kShadowLookupCompare), or LESS under shadow-compare-less.
lighting::DepthCompare shadowLookupCompare(Mutant mutant);

}  // namespace shaders
