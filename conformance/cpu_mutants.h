// The mutants that the shader cannot express (SPEC 7, mutation check): the
// shader is the model's, but the data the CPU hands the backend is wrong.
// They alter only what the backend draws, never the reference, so a check
// against the model's reference must catch them like any shader mutant.
//
//   demoted-light-still-lit: the shadow-mask assignment forgets that demoted
//     lights are demoted, so light selection keeps them and packs them with
//     channel -1 (no mask); the maps, baked with them, stay as they are. The
//     demoted light is lit in real time on top of its bake (SPEC 5.3).
//   legacy-falloff-baked: the maps are rebaked with lights whose
//     bake_falloff is inverse_squared baked with the legacy falloff (SPEC 3.6).
#pragma once

#include "lighting/frame.h"
#include "shaders/shader_variant.h"

namespace conformance {

// True for the mutants this file implements.
bool isCpuMutant(shaders::Mutant mutant);

// The frame the backend draws under `mutant`: frame `frame.index` of an
// altered copy of `frame.prepared` for a CPU mutant that applies to the
// scene, else `frame` itself. Altered copies are kept per (original prepared
// scene, mutant), so an animated scene or a repeated check rebuilds (and
// rebakes) nothing. Thread-safe.
lighting::Frame cpuMutantFrame(const lighting::Frame& frame, shaders::Mutant mutant);

}  // namespace conformance
