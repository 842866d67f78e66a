#include "reference/light_evaluation.h"

#include "reference/cookie_bound.h"
#include "reference/light_terms.h"
#include "reference/surface_inputs.h"
#include "reference/shadow_ray.h"
#include "reference/specular_bound.h"
#include "reference/tolerance_model.h"

#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>

#include <algorithm>
#include <cmath>
#include <optional>

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

// SPEC 3.8: the light's radiance `term` (bound `termBound`) times the lobe in
// direction L, whose float32 direction error is `lightError`.
void addSpecular(const LobeAtPoint& lobe, const Vec3& N, const Vec3& L, const VectorError& lightError, const Vec3& term,
                 const Vec3& termBound, LightSum& sum) {
  const LobeInputErrors errors{lobe.normalError, lobe.viewError, lightError};
  const SpecularBound s = specularWithBound(N, lobe.view, L, lobe.smoothness, errors);
  const Vec3 specular = term * s.value;
  sum.specular += specular;
  sum.specularBound += termBound * s.value + term * s.errorBound +
                       specular * (tol::kSpecularTermSteps * tol::kStepRoundoff);
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
                                                      const LookupError& error, const ShadowReceiver& receiver) const {
  ShadowFactor f;
  double s = 1, sLo = 1, sHi = 1;
  if (light.idealShadowLight) {
    // SPEC 3.9 `--ideal` is SPEC 3.6's visibility ray (shadow_ray.h).
    s = sLo = sHi = lightVisibility(*idealVisibility_, *light.idealShadowLight, p, N);
  } else {
    const ShadowLookup look = light.shadowMap->lookup(p, N, error, filterWeightPrecision_);
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

using terms::Vec3Of;

Vec3Of<FloatBound> uploaded(const Vec3& v) {
  return {FloatBound::uploaded(v.x), FloatBound::uploaded(v.y), FloatBound::uploaded(v.z)};
}

// An input whose float may be `error` off per component, and whose exact
// value ranges `spread` either side over the snapping square.
Vec3Of<FloatBound> boundedInput(const Vec3& v, double error, double spread) {
  return {FloatBound::input(v.x, error, v.x - spread, v.x + spread),
          FloatBound::input(v.y, error, v.y - spread, v.y + spread),
          FloatBound::input(v.z, error, v.z - spread, v.z + spread)};
}

Vec3Of<double> exact(const Vec3& v) { return {v.x, v.y, v.z}; }
Vec3 valueOf(const Vec3Of<FloatBound>& v) { return {v.x.value, v.y.value, v.z.value}; }
Vec3 errorOf(const Vec3Of<FloatBound>& v) { return {v.x.error, v.y.error, v.z.error}; }

// SPEC 3.5's shadowMask as shadowMaskAttenuation computes it: mix(1, m, s),
// inherited from 1 (1 - s) + m s, with the filtered mask's error; exactly 1
// for a light without a channel.
FloatBound maskFactor(double strength, const ShadowMaskAtPoint* mask, int channel) {
  if (!mask || channel < 0) return FloatBound(1.0);
  const FloatBound s = FloatBound::uploaded(strength);
  const FloatBound m = FloatBound::input(mask->value[channel], mask->error[channel]);
  return FloatBound(1.0) * (FloatBound(1.0) - s) + m * s;
}

// The light's textures as lightTextureAttenuation gives them: the cookie
// (SPEC 3.10, its value and bound from cookie_bound.h) times the real-time
// shadow (SPEC 3.9: any value of the admissible interval [lo, hi] the
// lookups allow, and the fade's error), one product.
FloatBound textureFactor(const CookieBound* cookie, const ShadowFactor* shadow) {
  const FloatBound c = cookie ? FloatBound::input(cookie->value, cookie->errorBound) : FloatBound(1.0);
  if (!shadow) return c;
  const double highest = std::max(shadow->hi, shadow->value);
  const FloatBound s =
      FloatBound::input(shadow->value,
                        (shadow->hi - shadow->lo) + shadow->fadeError + highest * tol::kShadowAttenuationSteps * tol::kStepRoundoff,
                        std::min(shadow->lo, shadow->value), highest);
  return c * s;
}

// SPEC 3.9's cap on ambiguity counts the pixels where a shadowed light adds
// light (its unshadowed term > 0), with the widest of their intervals.
void noteShadow(const ShadowFactor& shadow, bool adds, LightSum& sum) {
  if (!adds) return;
  if (!sum.shadowed || shadow.sHi - shadow.sLo > sum.widestShadowSpan) {
    sum.widestShadowSpan = shadow.sHi - shadow.sLo;
    sum.widestShadowLo = shadow.sLo;
    sum.widestShadowHi = shadow.sHi;
  }
  sum.shadowed = true;
}

}  // namespace

void LightEvaluator::accumulate(const std::vector<int>& lights, const Vec3& p, const Vec3& N,
                                const PositionContext& where, LightSum& sum, const ShadowMaskAtPoint* mask,
                                const LobeAtPoint* lobe, const ShadowReceiver* receiver) const {
  const double u = tol::kUnitRoundoff, step = tol::kStepRoundoff;
  // What the fragment stage gets: the camera-relative p and the unit N, each
  // off by its inputs' bound (reference/surface_inputs.h); p ranges over the
  // snapped square (PositionContext::snapMove).
  const Vec3 relative = p - where.camera;
  const SurfaceErrors inputs = where.inputs     ? *where.inputs
                               : where.valueOnly ? SurfaceErrors{}
                                                 : inputErrorsOfMagnitude(glm::length(relative) + where.objectExtent);
  // The deferred light pass does not interpolate p: it rebuilds it from the
  // G-buffer's depth, off by the reconstruction's error alone.
  const bool rebuilt = where.reconstructionError > 0;
  const double positionError = rebuilt ? where.reconstructionError : inputs.position;
  const Vec3Of<FloatBound> nBound = boundedInput(N, inputs.normal, inputs.normal);
  // The position error as a length, for the cookie and shadow lookups (the
  // reconstruction's is one already).
  const double pointError = rebuilt ? positionError : std::sqrt(3.0) * positionError;
  Vec3 absoluteSum(0.0);
  for (int index : lights) {
    const Prepared& light = lights_[index];
    ++sum.evaluations;
    const FloatBound shadowMask = maskFactor(light.shadowStrength, mask, light.shadowMaskChannel);
    const Vec3 towardLight = light.directional ? light.towardLight : light.position - p;
    const double distance = std::max(glm::length(towardLight), std::sqrt(kMinDistanceSquared));
    // Where the lookups see the point: its own error, the light's uploaded
    // position's (one rounding per component) for a local light.
    const Vec3 lightRelative = light.position - where.camera;
    const double lookupError =
        pointError + (light.directional ? 0.0 : std::sqrt(3.0) * u * glm::length(lightRelative));
    std::optional<CookieBound> cookie;
    if (light.cookieLight) {
      // A directional tiling is anchored at the world origin; a
      // camera-relative lookup adds the camera's share in double
      // (docs/tolerances.md "Cookies").
      const double over = light.directional ? glm::length(relative) : distance;
      cookie = cookieWithBound(*light.cookieLight, p, lookupError + tol::kCookieCoordinateSteps * step * over,
                               filterWeightPrecision_);
    }
    std::optional<ShadowFactor> shadow;
    if (receiver && (light.shadowMap || light.idealShadowLight))
      shadow = shadowAt(light, p, N, {lookupError}, *receiver);
    const FloatBound textures = textureFactor(cookie ? &*cookie : nullptr, shadow ? &*shadow : nullptr);

    // The radiance, operation for operation as the shader evaluates it
    // (shaders/light_terms.glsl through reference/light_terms.h): its exact
    // value and its float32 bound in one evaluation, or the exact value alone.
    if (where.valueOnly) {
      const double c = cookie ? cookie->value : 1.0, s = shadow ? shadow->value : 1.0;
      const Vec3Of<double> exactRadiance =
          light.directional
              ? terms::directionalRadiance(exact(light.finalColor), exact(light.towardLight), shadowMask.value * (c * s),
                                           exact(N))
              : terms::localRadiance(exact(light.finalColor), exact(lightRelative), light.invRangeSq,
                                     exact(light.spotDirection), light.spot.a, light.spot.b, shadowMask.value, c * s,
                                     exact(relative), exact(N));
      const Vec3 term(exactRadiance.x, exactRadiance.y, exactRadiance.z);
      sum.value += term;
      sum.contributing += glm::vec<3, double>(glm::greaterThan(term, Vec3(0.0)));
      if (lobe) addSpecular(*lobe, N, light.directional ? light.towardLight : towardLight * (1.0 / distance),
                            VectorError{}, term, Vec3(0.0), sum);
      continue;
    }
    const Vec3Of<FloatBound> color = uploaded(light.finalColor);
    Vec3Of<FloatBound> radiance;
    if (light.directional) {
      radiance = terms::directionalRadiance(color, uploaded(light.towardLight), shadowMask * textures, nBound);
    } else {
      // p over the snapped square, but no nearer the light than half its
      // distance: a square that reaches the light is one whose value changes
      // without bound, which the sub-pixel term's first-order change of the
      // value does not hold either; the range stops where the light's
      // distance has halved.
      const Vec3Of<FloatBound> pBound =
          boundedInput(relative, positionError, std::min(where.snapMove, 0.5 * distance));
      radiance = terms::localRadiance(color, uploaded(lightRelative), FloatBound::uploaded(light.invRangeSq),
                                      uploaded(light.spotDirection), FloatBound::uploaded(light.spot.a),
                                      FloatBound::uploaded(light.spot.b), shadowMask, textures, pBound, nBound);
    }
    const Vec3 term = valueOf(radiance);
    const Vec3 termBound = errorOf(radiance);
    if (shadow && where.snapMove > 0 && light.shadowMap) {
      // A compare's edge inside the snapping square may put the point a
      // centre sees in shadow (or out of it) where none of the sampled
      // points of the square lies. A hard shadow's edge is a texel's: its
      // lookups over the whole square give the factor's range there. A
      // filtered shadow is continuous in the map's coordinates, which the
      // sampled points follow, but each tap compares, and flips where the
      // receiver's depth crosses its texel's (at grazing light, acne a few
      // pixels wide): its lookups with the receiver's depth over the square
      // give the range. The term's range with it (p already ranges over the
      // square) bounds the change.
      const bool hard = light.shadowMap->projection().spec.filter == lighting::ShadowFilter::Hard;
      const LookupError overSquareError =
          hard ? LookupError{lookupError + where.snapMove} : LookupError{lookupError, where.snapMove};
      const ShadowFactor square = shadowAt(light, p, N, overSquareError, *receiver);
      if (square.hi - square.lo > shadow->hi - shadow->lo) {
        const FloatBound squareTextures = textureFactor(cookie ? &*cookie : nullptr, &square);
        const Vec3Of<FloatBound> overSquare =
            light.directional
                ? terms::directionalRadiance(color, uploaded(light.towardLight), shadowMask * squareTextures, nBound)
                : terms::localRadiance(color, uploaded(lightRelative), FloatBound::uploaded(light.invRangeSq),
                                       uploaded(light.spotDirection), FloatBound::uploaded(light.spot.a),
                                       FloatBound::uploaded(light.spot.b), shadowMask, squareTextures,
                                       boundedInput(relative, positionError, std::min(where.snapMove, 0.5 * distance)),
                                       nBound);
        const auto change = [](const FloatBound& c) { return std::max(c.hi - c.value, c.value - c.lo); };
        sum.shadowEdgeChange += Vec3(change(overSquare.x), change(overSquare.y), change(overSquare.z));
      }
    }
    if (shadow) {
      // Whether the light adds anything unshadowed: the exact term without s.
      const double c = cookie ? cookie->value : 1.0;
      const Vec3Of<double> unshadowed =
          light.directional
              ? terms::directionalRadiance(exact(light.finalColor), exact(light.towardLight), shadowMask.value * c,
                                           exact(N))
              : terms::localRadiance(exact(light.finalColor), exact(lightRelative), light.invRangeSq,
                                     exact(light.spotDirection), light.spot.a, light.spot.b, shadowMask.value, c,
                                     exact(relative), exact(N));
      noteShadow(*shadow, unshadowed.x > 0 || unshadowed.y > 0 || unshadowed.z > 0, sum);
    }
    sum.value += term;
    sum.contributing += glm::vec<3, double>(glm::greaterThan(term, Vec3(0.0)));
    absoluteSum += term;
    sum.errorBound += termBound;
    if (!lobe) continue;
    // The lobe's own bound (reference/specular_bound.h) takes L's error
    // split along and across L.
    if (light.directional) {
      const VectorError uploadedL{tol::kNormalizedDirectionSteps * step, tol::kNormalizedDirectionSteps * step};
      addSpecular(*lobe, N, light.towardLight, uploadedL, term, termBound, sum);
    } else {
      const Vec3 L = towardLight * (1.0 / distance);
      const VectorError lightError{tol::kNormalizedLengthSteps * step,
                                   std::min(2.0, lookupError / distance + tol::kNormalizedDirectionSteps * step)};
      addSpecular(*lobe, N, L, lightError, term, termBound, sum);
    }
  }
  // The running sum rounds once per added term, either neighbour (1 ULP).
  sum.errorBound += absoluteSum * (double(lights.size()) * Float32Precision::kAddUlps * kUlpRelative);
  sum.specularBound += sum.specular * (double(lights.size()) * step);
}

}  // namespace reference
