// Test-only mutants of the model (SPEC 7, mutation check). Each is selected by
// the MUTANT specialization constant and never by default; the numbers are
// shaders::Mutant (shader_variant.h).
#ifndef LIGHTCTS_MUTANTS_GLSL
#define LIGHTCTS_MUTANTS_GLSL

const int MUTANT_NONE = 0;
const int MUTANT_DISTANCE_CLAMP_1EM4 = 1;  // distSqr clamped at 1e-4 instead of 1e-5

#endif
