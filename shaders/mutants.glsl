// Test-only mutants of the model (SPEC 7, mutation check). Each is selected by
// the MUTANT specialization constant and never by default; the numbers are
// shaders::Mutant (shader_variant.h), the --mutant spellings and what each
// breaks are listed in shader_variant.cpp. Every use is a test of
// `MUTANT == MUTANT_X` on a constant, so the shipped shader (MUTANT = 0)
// compiles each of them out.
#ifndef LIGHTCTS_MUTANTS_GLSL
#define LIGHTCTS_MUTANTS_GLSL

const int MUTANT_NONE = 0;
const int MUTANT_DISTANCE_CLAMP_1EM4 = 1;         // distSqr clamped at 1e-4 instead of 1e-5
const int MUTANT_UNSQUARED_RANGE = 2;             // rangeAtt without the outer square
const int MUTANT_UNSQUARED_SPOT = 3;              // spotAtt without the square
const int MUTANT_FULL_SPOT_ANGLE = 4;             // the cone uses the full angle as if it were the half angle
const int MUTANT_UNSANITISED_OBJECT_LOOP = 5;     // the per-object loop runs to count, not min(count, 8)
const int MUTANT_HALF_PRECISION_ATTENUATION = 6;  // attenuation rounded through a 16-bit float
const int MUTANT_ABSOLUTE_COORDINATES = 7;        // positions in absolute world coordinates, float32
const int MUTANT_VERTEX_NORMAL_NOT_NORMALISED = 8;  // legacy vertex lights use rotation * scale * normal
const int MUTANT_DIRECTIONAL_NOT_SATURATED = 9;   // directional dot(N, L) not clamped at 0
const int MUTANT_SPOT_DIRECTION_FLIPPED = 10;     // spotDir = direction, not -direction
const int MUTANT_LOCAL_NOT_SATURATED = 11;        // point and spot dot(N, L) not clamped at 0
const int MUTANT_LEGACY_VERTEX_LIGHTS_DROPPED = 12;  // legacy list positions 4-7 never lit
const int MUTANT_SHADOW_MASK_CHANNEL_OFF_BY_ONE = 13;  // a mixed light reads mask channel (c + 1) mod 4
const int MUTANT_SHADOW_STRENGTH_IGNORED = 14;        // shadowMask = mask[c], as if every strength were 1
// 15 (demoted-light-still-lit) and 16 (legacy-falloff-baked) change the data
// the CPU hands over, not the shader (conformance/cpu_mutants.h).
const int MUTANT_UNCLAMPED_LDR_DECODE = 17;           // the ldr8 composite decodes -log2(x), no max(x, 1/255)
// 18 (point-volume-outside-only) changes the light pass's pipeline state
// (front faces, depth test LESS_OR_EQUAL for icosphere volumes), not the shader.
const int MUTANT_D2_WITHOUT_EPSILON = 19;         // d2 = square(nh2 (r2 - 1) + 1), no 1.00001 (SPEC 3.8)
const int MUTANT_LH2_NOT_CLAMPED = 20;            // specularStrength divides by lh2, not max(0.1, lh2)
const int MUTANT_F0_ALBEDO_ALWAYS = 21;           // F0 = albedo whatever the metallic
const int MUTANT_VIEW_ABSOLUTE_COORDINATES = 22;  // V = normalize(camera - p) in absolute float32 coordinates
const int MUTANT_HALF_VECTOR_NOT_NORMALISED = 23; // H = L + V, not normalised
const int MUTANT_DIRECTIONAL_COOKIE_CLAMPED = 24; // directional cookie clamped to edge, not tiled (SPEC 3.10)
const int MUTANT_CUBE_COOKIE_ROTATED = 25;        // point cookie sampled at the direction turned 90 degrees about y
const int MUTANT_COOKIE_V_FLIPPED = 26;           // 2D cookies sampled at 1 - v: image row 0 taken as v = 1
// 27 (shadow-compare-less) changes the compare samplers the backends create, not the shader.
const int MUTANT_SHADOW_DEPTH_BIAS_IGNORED = 28;  // p' without depth_bias * L (SPEC 3.9)
const int MUTANT_SHADOW_NORMAL_BIAS_ALONG_L = 29; // the normal bias along L instead of N
const int MUTANT_SHADOW_TEXEL_CENTRES_SHIFTED = 30;  // 2D lookups half a texel off the texel centres
const int MUTANT_SHADOW_FADE_IGNORED = 31;        // fade = 0 whatever shadow_distance
const int MUTANT_CUBE_SHADOW_WRONG_AXIS = 32;     // the cube face chosen with x and z exchanged
const int MUTANT_SHADOW_STRENGTH_AS_POWER = 33;   // shadowAtten = saturate(pow(s, strength) + fade)

#endif
