// Which variant of the one set of shaders a backend builds. The shipped model
// is `specialised` with no mutant: features a frame does not use are switched
// off by specialization constants (shaders/lighting.glsl). The full shader and
// the mutants exist for tests only.
#pragma once

#include "lighting/deferred_lights.h"
#include "lighting/raster_state.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace shaders {

// Deliberately wrong variants of the model (SPEC 7, mutation check), selected
// by the specialization constant MUTANT. 0 is the model itself; no other
// value is ever a default. The numbers are shared with shaders/mutants.glsl.
enum class Mutant : int {
  None = 0,
  DistanceClamp1em4 = 1,         // distSqr clamped at 1e-4 instead of 1e-5 (SPEC 3.2)
  UnsquaredRange = 2,            // rangeAtt without the outer square (SPEC 3.2)
  UnsquaredSpot = 3,             // spotAtt without the square (SPEC 3.2)
  FullSpotAngle = 4,             // the full cone angle used as the half angle (SPEC 3.3)
  UnsanitisedObjectLoop = 5,     // the per-object loop runs to count, not min(count, 8) (SPEC 5.2)
  HalfPrecisionAttenuation = 6,  // attenuation rounded through a 16-bit float (SPEC 7)
  AbsoluteCoordinates = 7,       // positions in absolute world coordinates, float32 (SPEC 7)
  VertexNormalNotNormalised = 8, // legacy vertex lights with the unnormalised normal (SPEC 4)
  DirectionalNotSaturated = 9,   // directional dot(N, L) not clamped at 0 (SPEC 3.1)
  SpotDirectionFlipped = 10,     // spotDir = direction instead of -direction (SPEC 3.2)
  LocalNotSaturated = 11,        // point and spot dot(N, L) not clamped at 0 (SPEC 3.2)
  LegacyVertexLightsDropped = 12,  // legacy list positions 4-7 (vertex lights) never lit (SPEC 4)
  ShadowMaskChannelOffByOne = 13,  // a mixed light reads shadow-mask channel (c + 1) mod 4 (SPEC 3.5)
  ShadowStrengthIgnored = 14,      // shadowMask = mask[c], whatever the strength (SPEC 3.5)
  // CPU mutants: the shader is the model's; the data handed to the backend is
  // wrong (conformance/cpu_mutants.h).
  DemotedLightStillLit = 15,       // a demoted mixed light is packed and lit in real time besides its bake (SPEC 5.3)
  LegacyFalloffBaked = 16,         // lights with inverse_squared bake_falloff baked with the legacy falloff (SPEC 3.6)
  UnclampedLdrDecode = 17,         // shader: the ldr8 composite decodes -log2(x) without max(x, 1/255) (SPEC 3.7)
  // Pipeline-state mutant: the backends draw icosphere light volumes front
  // faces with depth test LESS_OR_EQUAL when they see it (no GLSL change).
  PointVolumeOutsideOnly = 18,     // point (and sphere-shaped spot) volumes drawn without the camera-inside handling (SPEC 3.7)
  // The specular BRDF (SPEC 3.8), shader mutants.
  D2WithoutEpsilon = 19,           // d2 = square(nh2 (r2 - 1) + 1), without the 1.00001
  Lh2NotClamped = 20,              // specularStrength divides by lh2, not max(0.1, lh2)
  F0AlbedoAlways = 21,             // F0 = albedo whatever the metallic
  ViewAbsoluteCoordinates = 22,    // V = normalize(camera - p) from absolute float32 coordinates
  HalfVectorNotNormalised = 23,    // H = L + V, not SafeNormalize(L + V)
  // Light cookies (SPEC 3.10), shader mutants. (Dropping the spot cookie's
  // q.z <= 0 rule is no mutant: spotAtt is already 0 there, docs/tolerances.md "Cookies".)
  DirectionalCookieClamped = 24,   // the directional cookie clamped to edge instead of tiled
  CubeCookieRotated = 25,          // the point cookie's cube sampled turned 90 degrees about y
  CookieVFlipped = 26,             // 2D cookies sampled at 1 - v (image row 0 taken as v = 1)
  // Real-time shadow maps (SPEC 3.9). 27 changes the compare samplers the
  // backends create (no GLSL change); the others are shader mutants.
  ShadowCompareLess = 27,          // the shadow compare is LESS instead of LESS_OR_EQUAL
  ShadowDepthBiasIgnored = 28,     // p' without depth_bias * L
  ShadowNormalBiasAlongL = 29,     // p' = p + normal_bias * L + depth_bias * L
  ShadowTexelCentresShifted = 30,  // every 2D lookup half a texel off the texel centres
  ShadowFadeIgnored = 31,          // fade = 0 whatever shadow_distance
  CubeShadowWrongAxis = 32,        // the cube face chosen with x and z exchanged
  ShadowStrengthAsPower = 33,      // shadowAtten = saturate(pow(s, strength) + fade)
};

struct MutantName {
  Mutant mutant;
  std::string_view name;  // the --mutant spelling
  std::string_view what;  // one line for listings and reports
};
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

// The rule the light pass draws volumes by under `mutant`: the only
// pipeline-state mutant changes it, every other mutant leaves the model's.
lighting::VolumeRule volumeRule(Mutant mutant);

// The compare the shadow samplers use under `mutant`: the model's
// (lighting::kShadowLookupCompare), or LESS under shadow-compare-less.
lighting::DepthCompare shadowLookupCompare(Mutant mutant);

}  // namespace shaders
