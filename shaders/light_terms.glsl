// SPEC 3.1-3.2's light terms, written once for two compilers: glslang
// compiles them into every shader that lights (lighting.glsl includes this
// file), and g++ into the reference (reference/light_terms.h includes it),
// which evaluates the very same operations three ways: exactly in double
// (the reference value), as an error bound from the precision table
// (reference/float_bound.h), and as float32 with perturbed roundings (the
// bound's property tests). A bound therefore follows the shader operation
// for operation: an operation added here is bounded, and tested, with it.
//
// So this file keeps to what both languages read alike: `real` and `real3`
// for float and vec3 (the includer defines them), no swizzles, no `out`
// parameters, every constant as real(...) (its float32 rounding is part of
// the bound), and every operation whose precision the APIs leave open
// through admissible.glsl's functions (quotient, inverseSqrt, dotProduct,
// multiplyAdd) rather than an operator. A mutant tests MUTANT_ACTIVE(name),
// which the reference defines as false. LIGHTCTS_TERM opens each function
// (the reference's template head).

// SPEC 1.
LIGHTCTS_TERM real saturate(real x) { return clamp(x, real(0.0), real(1.0)); }
LIGHTCTS_TERM real square(real x) { return x * x; }

// SPEC 3.2: distSqr = max(dot(ray, ray), 1e-5), so L and 1/distSqr stay
// finite when the point lies on the light.
LIGHTCTS_TERM real clampedDistanceSquared(real3 ray) {
  real minimum = MUTANT_ACTIVE(MUTANT_DISTANCE_CLAMP_1E_4) ? real(1e-4) : real(1e-5);
  return max(dotProduct(ray, ray), minimum);
}

// SPEC 3.2: rangeAtt = square(saturate(1 - square(distSqr * invRangeSq))).
LIGHTCTS_TERM real rangeAttenuation(real distSqr, real invRangeSq) {
  real q = distSqr * invRangeSq;
  real window = saturate(multiplyAdd(-q, q, real(1.0)));
  if (MUTANT_ACTIVE(MUTANT_UNSQUARED_RANGE)) return window;
  return square(window);
}

// SPEC 3.2 with the factors of SPEC 3.3 (a, b; the CPU applied 3.4's legacy
// inner angle): spotAtt = square(saturate(dot(spotDir, L) * a + b)). A point
// light has a = 0, b = 1: exactly 1.
LIGHTCTS_TERM real spotAttenuation(real3 spotDirection, real3 L, real a, real b) {
  real cone = saturate(multiplyAdd(dotProduct(spotDirection, L), a, b));
  if (MUTANT_ACTIVE(MUTANT_UNSQUARED_SPOT)) return cone;
  return square(cone);
}

// SPEC 3.2's L at camera-relative p: ray * inversesqrt(distSqr).
LIGHTCTS_TERM real3 towardLocalLight(real3 lightPosition, real3 p) {
  real3 ray = lightPosition - p;
  return ray * inverseSqrt(clampedDistanceSquared(ray));
}

// SPEC 3.2: finalColor * saturate(dot(N, L)) * attenuation, the radiance the
// BRDF weighs, for a point or spot light at camera-relative `lightPosition`
// (`invRangeSq`, spot factors a and b) lighting camera-relative p with unit
// normal N. `mask` is SPEC 3.5's shadowMask and `textures` the product of
// the cookie (SPEC 3.10) and the real-time shadow (SPEC 3.9), both 1 when
// the light has none: they multiply the attenuation in this order.
LIGHTCTS_TERM real3 localRadiance(real3 color, real3 lightPosition, real invRangeSq, real3 spotDirection, real a,
                                  real b, real mask, real textures, real3 p, real3 N) {
  real3 ray = lightPosition - p;
  real distSqr = clampedDistanceSquared(ray);
  real3 L = ray * inverseSqrt(distSqr);
  real attenuation = quotient(rangeAttenuation(distSqr, invRangeSq), distSqr);
  if (SPOT_LIGHTS) attenuation = attenuation * spotAttenuation(spotDirection, L, a, b);
  attenuation = attenuation * mask;
  attenuation = attenuation * textures;
  attenuation = mutantAttenuationPrecision(attenuation);
  real cosine = dotProduct(N, L);
  if (!MUTANT_ACTIVE(MUTANT_LOCAL_NOT_SATURATED)) cosine = saturate(cosine);
  return color * (cosine * attenuation);
}

// SPEC 3.1: finalColor * saturate(dot(N, L)) * attenuation for a directional
// light with L = -direction; `attenuation` is the shadow mask times the
// cookie and the shadow, as for localRadiance.
LIGHTCTS_TERM real3 directionalRadiance(real3 color, real3 L, real attenuation, real3 N) {
  real cosine = dotProduct(N, L);
  if (!MUTANT_ACTIVE(MUTANT_DIRECTIONAL_NOT_SATURATED)) cosine = saturate(cosine);
  return color * (cosine * attenuation);
}
