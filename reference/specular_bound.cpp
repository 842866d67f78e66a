#include "reference/specular_bound.h"

#include "lighting/brdf.h"
#include "lighting/light_math.h"
#include "reference/tolerance_model.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace reference {

using namespace lighting;
namespace tol = tolerance;

namespace {

struct Interval {
  double lo, hi;
};

// |float(a . b) - a . b| for unit a, b at cosine c, each off by its VectorError.
double dotError(double c, const VectorError& a, const VectorError& b) {
  const double sine = std::sqrt(std::max(0.0, 1.0 - c * c));
  return std::abs(c) * (a.length + b.length) + sine * (a.direction + b.direction) + a.direction * b.direction +
         tol::kUnitDotRoundingSteps * tol::kStepRoundoff;
}

// [x - e, x + e] through saturate and square, both monotone on [0, 1], then
// the square's own rounding.
Interval saturatedSquare(double x, double e, bool anything) {
  const double u = tol::kStepRoundoff;
  const double lo = anything ? 0.0 : saturate(x - e);
  const double hi = anything ? 1.0 : saturate(x + e);
  return {lo * lo * (1 - u), hi * hi * (1 + u)};
}

}  // namespace

SpecularBound specularWithBound(const Vec3& N, const Vec3& V, const Vec3& L, double smoothness,
                                const LobeInputErrors& e) {
  const double u = tol::kStepRoundoff;
  const double roughness = square(1.0 - smoothness);
  SpecularBound out;
  out.value = specularStrength(N, V, L, roughness);
  // Smoothness 1 is exact in float, so r2 = 0 exactly and the lobe is 0
  // exactly on both sides.
  if (roughness == 0) return out;

  // H = SafeNormalize(L + V). The sum rounds once per component; the part of
  // an error dh across h turns H by |dh| / |h| (first order), and
  // normalising adds its own length and direction errors. Where |dh| reaches
  // half of |h|, H may point anywhere.
  const Vec3 h = L + V;
  const double length = glm::length(h);
  const double hError = e.light.length + e.light.direction + e.view.length + e.view.direction +
                        tol::kVectorAddSteps * u;
  out.halfVectorAmbiguous = 2.0 * hError >= length;
  const Vec3 H = safeNormalize(h);
  const VectorError half{tol::kNormalizedLengthSteps * u,
                         out.halfVectorAmbiguous ? 2.0 : hError / length + tol::kNormalizedDirectionSteps * u};
  const double nh = glm::dot(N, H), lh = glm::dot(L, H);
  const Interval nh2 = saturatedSquare(nh, dotError(nh, e.normal, half), out.halfVectorAmbiguous);
  const Interval lh2 = saturatedSquare(lh, dotError(lh, e.light, half), out.halfVectorAmbiguous);

  // roughness = square(1 - float(smoothness)), r2 = square(roughness): the
  // rounding of smoothness (u s) is relative u s / (1 - s) in 1 - s, doubled
  // by each square, plus one rounding per operation.
  const double oneMinus = 1.0 - smoothness;
  const double roughnessRel = 2.0 * (u * smoothness + u * oneMinus) / oneMinus + u;
  const double r2 = square(roughness);
  const double r2Rel = 2.0 * roughnessRel + u;
  const Interval rough{roughness * (1 - roughnessRel), roughness * (1 + roughnessRel)};
  const Interval r2i{r2 * (1 - r2Rel), r2 * (1 + r2Rel)};

  // d = nh2 (r2 - 1) + 1.00001 falls as nh2 grows and rises with r2. Its
  // roundings: r2 - 1, the product and the sum (each u times a magnitude of
  // at most 1 + d), and the constant itself, which float32 cannot hold:
  // |float(1.00001) - 1.00001| = 1.36e-8, relative 1.4e-3 of d at the peak
  // of smoothness 1 - a sizeable part of the bound there.
  const double constantError = std::abs(double(float(kLobeDenominatorOffset)) - kLobeDenominatorOffset);
  double dLo = nh2.hi * (r2i.lo - 1.0) + kLobeDenominatorOffset;
  double dHi = nh2.lo * (r2i.hi - 1.0) + kLobeDenominatorOffset;
  const double dRounding = u * (2.0 * nh2.hi + dHi) + constantError;
  // saturate keeps nh2 <= 1 in float too, so d >= r2 + 1e-5 less its rounding.
  dLo = std::max(dLo - dRounding, r2i.lo + (kLobeDenominatorOffset - 1.0) - dRounding);
  dHi += dRounding;
  const Interval d2{dLo * dLo * (1 - u), dHi * dHi * (1 + u)};
  const Interval m{std::max(kMinLh2, lh2.lo), std::max(kMinLh2, lh2.hi)};
  const Interval k{(rough.lo * 4.0 + 2.0) * (1 - 2 * u), (rough.hi * 4.0 + 2.0) * (1 + 2 * u)};

  // The quotient: two products and a divide (2.5 ULP in Vulkan's GLSL).
  const double quotientRel = tol::kLobeQuotientSteps * u;
  const double lo = r2i.lo / (d2.hi * m.hi * k.hi) * (1 - quotientRel);
  const double hi = r2i.hi / (d2.lo * m.lo * k.lo) * (1 + quotientRel);
  out.errorBound = std::max(hi - out.value, out.value - lo);
  return out;
}

}  // namespace reference
