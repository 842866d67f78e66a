// The two halves of the physical limit (docs/performance.md): the arithmetic
// of one pixel-light evaluation, counted from shaders/lighting.glsl
// (localLight) and shaders/forward.frag (the accumulation), and the measured
// peak rate (suite/bench/peak_rate.cpp).
#include "suite/bench/lighting_cost.h"

#include "suite/bench/peak_rate.h"

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

constexpr int sumOfSteps() {
  int total = 0;
  for (const Step& s : kSteps) total += s.flops;
  return total;
}
static_assert(sumOfSteps() == 45, "docs/performance.md's table says 45 flops per pixel-light");

}  // namespace

double flopsPerPixelLight() { return double(sumOfSteps()); }

double measurePeakGflops(int repetitions) { return measurePeakRate(repetitions).gflops; }

}  // namespace bench
