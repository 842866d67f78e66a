// The two halves of the physical limit (docs/performance.md): the arithmetic
// of one pixel-light evaluation, counted from shaders/lighting.glsl
// (localLight) and shaders/forward.frag (the accumulation), and the measured
// peak rate (suite/bench/peak_rate.cpp).
#include "suite/bench/lighting_cost.h"

#include "suite/bench/peak_rate.h"

#include <cstddef>

namespace bench {
namespace {

// One row per operation, in the order localLight executes them, for a spot
// light (SPOT_LIGHTS on: a point light then runs the same code with a = 0,
// b = 1), no shadow mask (SHADOW_MASK off folds shadowMaskAttenuation to 1),
// mutants off. Conventions (docs/performance.md): add, sub, mul = 1;
// FMA = 2; dot(vec3, vec3) = 5 (3 mul + 2 add); max/min = 1; clamp
// (saturate) = 2; inversesqrt = 1 and division = 1 (one instruction each on
// a GPU's special-function unit; llvmpipe spends more: this keeps the count,
// and so the limit, a lower bound). Branches, loads and the loop are not flops.
struct Step {
  const char* what;
  int flops;
};
constexpr Step kSteps[] = {
    {"ray = light.position.xyz - p (3 sub)", 3},
    {"dot(ray, ray)", 5},
    {"distSqr = max(..., 1e-5)", 1},
    {"inversesqrt(distSqr)", 1},
    {"L = ray * rsq (3 mul)", 3},
    {"distSqr * invRangeSq", 1},
    {"square(...)", 1},
    {"1.0 - ...", 1},
    {"saturate(...)", 2},
    {"square(window)", 1},
    {"rangeAtt / distSqr", 1},
    {"dot(spotDirection, L)", 5},
    {"... * a + b (FMA)", 2},
    {"saturate(...)", 2},
    {"square(cone)", 1},
    {"attenuation *= spotAtt", 1},
    {"cosine = dot(N, L)", 5},
    {"saturate(cosine)", 2},
    {"cosine * attenuation", 1},
    {"light.color.rgb * (...) (3 mul)", 3},
    {"light += ... in forward.frag (3 add)", 3},
};

// SPEC 3.8's lobe per light (specularStrength and addLight in
// shaders/lighting.glsl), on top of the rows above for an srp material.
constexpr Step kSpecularSteps[] = {
    {"h = L + V (3 add)", 3},
    {"dot(h, h)", 5},
    {"max(..., FLT_MIN)", 1},
    {"inversesqrt(...)", 1},
    {"H = h * rsq (3 mul)", 3},
    {"dot(N, H)", 5},
    {"saturate(...)", 2},
    {"nh2 = square(...)", 1},
    {"dot(L, H)", 5},
    {"saturate(...)", 2},
    {"lh2 = square(...)", 1},
    {"r2 = square(roughness)", 1},
    {"r2 - 1.0", 1},
    {"nh2 * (r2 - 1) + 1.00001 (FMA)", 2},
    {"d2 = square(...)", 1},
    {"max(0.1, lh2)", 1},
    {"roughness * 4 + 2 (FMA)", 2},
    {"d2 * ... * ... (2 mul)", 2},
    {"r2 / ...", 1},
    {"radiance * specularStrength (3 mul)", 3},
    {"sums.specular += ... (3 add)", 3},
};

template <std::size_t N>
constexpr int sumOf(const Step (&steps)[N]) {
  int total = 0;
  for (const Step& s : steps) total += s.flops;
  return total;
}
constexpr int sumOfSteps() { return sumOf(kSteps); }
static_assert(sumOfSteps() == 45, "docs/performance.md's table says 45 flops per pixel-light");
static_assert(sumOf(kSpecularSteps) == 46, "docs/performance.md's table says 46 more for the specular lobe");

}  // namespace

double flopsPerPixelLight() { return double(sumOfSteps()); }

double flopsOfSpecularLobe() { return double(sumOf(kSpecularSteps)); }

double measurePeakGflops(int repetitions) { return measurePeakRate(repetitions).gflops; }

}  // namespace bench
