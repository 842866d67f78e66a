#include "reference/light_evaluation.h"

#include "reference/cookie_bound.h"
#include "reference/shadow_ray.h"
#include "reference/specular_bound.h"
#include "reference/tolerance_model.h"

#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>

#include <algorithm>
#include <cmath>

namespace reference {

using namespace lighting;
namespace tol = tolerance;

LightEvaluator::LightEvaluator(const Scene& scene, Profile profile, const std::vector<double>& weights,
                               const std::vector<int>& shadowMaskChannels, double filterWeightPrecision,
                               const RealtimeShadows* shadows)
    : filterWeightPrecision_(filterWeightPrecision),
      idealVisibility_(shadows ? shadows->idealVisibility : nullptr),
      shadowDistance_(shadows ? shadows->shadowDistance : 0) {
  lights_.reserve(scene.lights.size());
  for (std::size_t i = 0; i < scene.lights.size(); ++i) {
    const Light& l = scene.lights[i];
    Prepared p;
    p.directional = l.type == LightType::Directional;
    p.finalColor = l.finalColor() * (weights.empty() ? 1.0 : weights[i]);
    p.position = l.position;
    p.towardLight = -l.direction;
    p.spotDirection = -l.direction;  // spotDir points back toward the light (SPEC 3.2)
    p.invRangeSq = inverseRangeSquared(l.range);
    p.spot = lightSpotFactors(l, profile);
    // SPEC 3.5: only a channel c >= 0 with strength s > 0 attenuates.
    if (!shadowMaskChannels.empty() && shadowMaskChannels[i] >= 0 && l.shadowStrength > 0) {
      p.shadowMaskChannel = shadowMaskChannels[i];
      p.shadowStrength = l.shadowStrength;
    }
    if (l.cookie && l.mode == LightMode::Realtime) p.cookieLight = &l;
    if (shadows && l.shadowMap && l.mode == LightMode::Realtime) {
      p.realtimeShadowStrength = l.shadowStrength;
      if (shadows->idealVisibility) p.idealShadowLight = &l;
      else if (i < shadows->mapOfLight.size()) p.shadowMap = shadows->mapOfLight[i];
    }
    lights_.push_back(p);
  }
}

namespace {

// SPEC 3.10: the radiance `term` (bound `termBound`) times the light's cookie
// at p, whose float32 lookup is off by at most cookie.errorBound.
void applyCookie(const CookieBound& cookie, Vec3& term, Vec3& termBound) {
  termBound = termBound * cookie.value + term * cookie.errorBound + term * (cookie.value * tol::kUnitRoundoff);
  term *= cookie.value;
}

// SPEC 3.8: the light's radiance `term` (bound `termBound`) times the lobe in
// direction L, whose float32 direction error is `lightError`.
void addSpecular(const LobeAtPoint& lobe, const Vec3& N, const Vec3& L, const VectorError& lightError, const Vec3& term,
                 const Vec3& termBound, LightSum& sum) {
  const LobeInputErrors errors{lobe.normalError, lobe.viewError, lightError};
  const SpecularBound s = specularWithBound(N, lobe.view, L, lobe.smoothness, errors);
  const Vec3 specular = term * s.value;
  sum.specular += specular;
  sum.specularBound += termBound * s.value + term * s.errorBound +
                       specular * (tol::kSpecularTermSteps * tol::kUnitRoundoff);
}

}  // namespace

// SPEC 3.9's shadowAtten at one point: its value and the interval the
// admissible lookups [s_lo, s_hi] give, and how far the fade's float32 view
// depth can move it.
struct ShadowFactor {
  double value = 1, lo = 1, hi = 1;
  double fadeError = 0;
  double sLo = 1, sHi = 1;
};

ShadowFactor LightEvaluator::shadowAt(const Prepared& light, const Vec3& p, const Vec3& N,
                                                      double positionError, const ShadowReceiver& receiver) const {
  ShadowFactor f;
  double s = 1, sLo = 1, sHi = 1;
  if (light.idealShadowLight) {
    // SPEC 3.9 `--ideal` is SPEC 3.6's visibility ray (shadow_ray.h).
    s = sLo = sHi = lightVisibility(*idealVisibility_, *light.idealShadowLight, p, N);
  } else {
    const ShadowLookup look = light.shadowMap->lookup(p, N, {positionError}, filterWeightPrecision_);
    s = look.s;
    sLo = look.lo;
    sHi = look.hi;
  }
  const double fade = shadowFade(shadowDistance_, receiver.viewDepth);
  const double strength = light.realtimeShadowStrength;
  f.value = shadowAttenuation(s, strength, fade);
  // Nondecreasing in s (strength >= 0): the ends of the interval bound it.
  f.lo = shadowAttenuation(sLo, strength, fade);
  f.hi = shadowAttenuation(sHi, strength, fade);
  f.sLo = sLo;
  f.sHi = sHi;
  // The fade's slope is 1 / (0.2 S) where it ramps; a view depth error that
  // crosses either end of the ramp moves it by no more than that.
  if (shadowDistance_ > 0) {
    const double ramp = 0.2 * shadowDistance_;
    const double z = receiver.viewDepth, dz = receiver.viewDepthError;
    if (z + dz > 0.8 * shadowDistance_ && z - dz < shadowDistance_) f.fadeError = std::min(1.0, dz / ramp);
  }
  return f;
}

namespace {

// The light's `term` (bound `termBound`) times its shadowAtten: the bound
// widens by the term times the span the admissible lookups allow (SPEC 3.9).
void applyShadow(const ShadowFactor& shadow, Vec3& term, Vec3& termBound, LightSum& sum) {
  const bool adds = term.x > 0 || term.y > 0 || term.z > 0;
  if (adds) {
    if (!sum.shadowed || shadow.sHi - shadow.sLo > sum.widestShadowSpan) {
      sum.widestShadowSpan = shadow.sHi - shadow.sLo;
      sum.widestShadowLo = shadow.sLo;
      sum.widestShadowHi = shadow.sHi;
    }
    sum.shadowed = true;
  }
  // A correct float32 evaluation may use any admissible shadowAtten, up to
  // the interval's top: the unshadowed term's own error and the roundings
  // scale with that, not with the reference's value.
  const double highest = std::max(shadow.hi, shadow.value);
  termBound = termBound * highest +
              term * ((shadow.hi - shadow.lo) + shadow.fadeError +
                      highest * (tol::kShadowAttenuationSteps * tol::kUnitRoundoff));
  term *= shadow.value;
}

}  // namespace

void LightEvaluator::accumulate(const std::vector<int>& lights, const Vec3& p, const Vec3& N,
                                const PositionContext& where, LightSum& sum, const ShadowMaskAtPoint* mask,
                                const LobeAtPoint* lobe, const ShadowReceiver* receiver) const {
  const double u = tol::kUnitRoundoff;
  const double pointMagnitude = glm::length(p - where.camera) + where.objectExtent;
  Vec3 absoluteSum(0.0);
  for (int index : lights) {
    const Prepared& light = lights_[index];
    ++sum.evaluations;
    // SPEC 3.5: shadowMask = lerp(1, mask[c], s). A filter error e in mask[c]
    // moves it by s e; the lerp and its product add kShadowMaskRoundingSteps.
    double shadowMask = 1, shadowMaskError = 0, maskRounding = 0;
    if (mask && light.shadowMaskChannel >= 0) {
      const int c = light.shadowMaskChannel;
      shadowMask = 1.0 + light.shadowStrength * (mask->value[c] - 1.0);
      shadowMaskError = light.shadowStrength * mask->error[c];
      maskRounding = tol::kShadowMaskRoundingSteps * u;
    }
    if (light.directional) {
      // SPEC 3.1: A * finalColor * saturate(dot(N, L)) * shadowMask.
      const double nl = saturate(glm::dot(N, light.towardLight));
      Vec3 term = light.finalColor * (nl * shadowMask);
      Vec3 termBound = term * (tol::kRoundingStepsPerLightTerm * u + maskRounding) +
                       light.finalColor * (shadowMask * tol::kUnitDotAbsError + nl * shadowMaskError);
      if (light.cookieLight) {
        // The tiling is anchored at the world origin; a camera-relative
        // lookup adds the camera's share in double (docs/tolerances.md "Cookies").
        const double distance = glm::length(p - where.camera);
        const double positionError = tol::kPositionRoundingSteps * u * pointMagnitude + where.reconstructionError +
                                     tol::kCookieCoordinateSteps * u * distance;
        applyCookie(cookieWithBound(*light.cookieLight, p, positionError, filterWeightPrecision_), term, termBound);
      }
      if (receiver && (light.shadowMap || light.idealShadowLight)) {
        const double positionError = tol::kPositionRoundingSteps * u * pointMagnitude + where.reconstructionError;
        applyShadow(shadowAt(light, p, N, positionError, *receiver), term, termBound, sum);
      }
      sum.value += term;
      sum.contributing += glm::vec<3, double>(glm::greaterThan(term, Vec3(0.0)));
      absoluteSum += term;
      sum.errorBound += termBound;
      // L = float(-direction): one rounding per component, in length and direction.
      const VectorError uploaded{tol::kNormalizedDirectionSteps * u, tol::kNormalizedDirectionSteps * u};
      if (lobe) addSpecular(*lobe, N, light.towardLight, uploaded, term, termBound, sum);
      continue;
    }
    // SPEC 3.2.
    const Vec3 ray = light.position - p;
    const double distSqr = std::max(glm::dot(ray, ray), kMinDistanceSquared);
    const Vec3 L = ray * (1.0 / std::sqrt(distSqr));
    const double nl = saturate(glm::dot(N, L));
    // rangeAtt and spotAtt are lighting::rangeAttenuation and spotAttenuation
    // (light_math.cpp) written out operation for operation, so they give the
    // same doubles: inlined because the error bound below needs the
    // intermediates q, g and s, which those functions square away. A change to
    // either formula there must be made here too.
    const double q = distSqr * light.invRangeSq;
    const double g = saturate(1.0 - q * q);
    const double rangeAtt = g * g;
    const double sRaw = glm::dot(light.spotDirection, L) * light.spot.a + light.spot.b;
    const double s = saturate(sRaw);
    const double spotAtt = s * s;
    const double falloff = shadowMask * rangeAtt / distSqr;
    Vec3 term = light.finalColor * (nl * spotAtt * falloff);

    // First-order error of the same formula in float32 (docs/tolerances.md):
    // the ray is off by the position error of both ends; that turns L by up
    // to rayError/d and changes distSqr by 2 rayError/d relative.
    const double distance = std::sqrt(distSqr);
    const double rayError = tol::kPositionRoundingSteps * u *
                                (pointMagnitude + glm::length(light.position - where.camera)) +
                            where.reconstructionError;
    const double directionError = std::min(1.0, tol::kUnitDotAbsError + rayError / distance);
    const double distSqrRelError = tol::kRoundingStepsPerLightTerm * u + std::min(1.0, 2.0 * rayError / distance);
    const double baseMagnitude = shadowMask * rangeAtt / distSqr;
    // Each product below is one factor's error times the other factors. A
    // factor at its kink (nl = 0 on a surface the light lies in, rangeAtt = 0
    // just past the range, spotAtt = 0 just outside the cone) is 0 in double
    // and may be above 0 where float32 and snapping put the point, so the
    // product of two such errors is all the error there is: the factors that
    // multiply an error are taken at the high end of what they may be over
    // the arithmetic's error and the snapped point (each is monotone in its
    // input).
    const double moved = where.snapMove / distance;
    const double directionHigh = std::min(1.0, directionError + moved);
    const double distSqrRelHigh = std::min(1.0, distSqrRelError + 2.0 * moved);
    const double qLow = q * (1.0 - distSqrRelHigh);
    const double gHigh = saturate(1.0 - qLow * qLow);
    const double sHigh = saturate(sRaw + std::abs(light.spot.a) * directionHigh);
    const double nlHigh = std::min(1.0, nl + directionHigh);
    const double spotHigh = sHigh * sHigh;
    // The shader clamps distSqr at kMinDistanceSquared, so its low end does too.
    const double distSqrLow = std::max(distSqr * (1.0 - distSqrRelHigh), kMinDistanceSquared);
    const double baseHigh = shadowMask * gHigh * gHigh / distSqrLow;
    const double fromChain = nl * spotAtt * baseMagnitude * distSqrRelError;
    const double fromNdotL = spotHigh * baseHigh * directionError;
    const double fromSpot = nlHigh * baseHigh * 2.0 * sHigh * std::abs(light.spot.a) * directionError;
    const double fromRange = nlHigh * spotHigh * shadowMask / distSqr * 4.0 * gHigh * q * q * distSqrRelError;
    // The mask's filtering error acts on the unmasked term.
    const double fromMask = nl * spotAtt * rangeAtt / distSqr * shadowMaskError;
    Vec3 termBound = light.finalColor * (fromChain + fromNdotL + fromSpot + fromRange + fromMask) +
                     term * maskRounding;
    if (light.cookieLight) {
      const double positionError = rayError + tol::kCookieCoordinateSteps * u * distance;
      applyCookie(cookieWithBound(*light.cookieLight, p, positionError, filterWeightPrecision_), term, termBound);
    }
    if (receiver && (light.shadowMap || light.idealShadowLight))
      applyShadow(shadowAt(light, p, N, rayError, *receiver), term, termBound, sum);
    sum.value += term;
    sum.contributing += glm::vec<3, double>(glm::greaterThan(term, Vec3(0.0)));
    absoluteSum += term;
    sum.errorBound += termBound;
    // L = ray * inversesqrt(distSqr): the ray's turn plus the normalisation.
    const VectorError lightError{tol::kNormalizedLengthSteps * u,
                                 std::min(2.0, rayError / distance + tol::kNormalizedDirectionSteps * u)};
    if (lobe) addSpecular(*lobe, N, L, lightError, term, termBound, sum);
  }
  // The running sum rounds once per added term.
  sum.errorBound += absoluteSum * (double(lights.size()) * u);
  sum.specularBound += sum.specular * (double(lights.size()) * u);
}

}  // namespace reference
