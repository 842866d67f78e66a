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

struct ShaderVariant {
  bool specialised = true;  // false: every feature on, whatever the frame uses
  Mutant mutant = Mutant::None;
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

// The compare the shadow samplers use under `mutant`: the model's
// (lighting::kShadowLookupCompare), or LESS under shadow-compare-less.
lighting::DepthCompare shadowLookupCompare(Mutant mutant);

}  // namespace shaders
