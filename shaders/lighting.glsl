// The lighting model of SPEC 3, written once. Every stage and every API uses
// these functions: Vulkan consumes the SPIR-V, OpenGL the GLSL that
// SPIRV-Cross makes of it. Nowhere else is a formula of SPEC 3 written for
// the GPU.
#ifndef LIGHTCTS_LIGHTING_GLSL
#define LIGHTCTS_LIGHTING_GLSL

#include "features.glsl"
#include "light_data.glsl"
#include "mutants.glsl"

// SPEC 1.
float saturate(float x) { return clamp(x, 0.0, 1.0); }
float square(float x) { return x * x; }

// SPEC 3.2: distSqr = max(dot(ray, ray), 1e-5), so L and 1/distSqr stay
// finite when the point lies on the light.
float clampedDistanceSquared(vec3 ray) {
  float minimum = MUTANT == MUTANT_DISTANCE_CLAMP_1EM4 ? 1e-4 : 1e-5;
  return max(dot(ray, ray), minimum);
}

// SPEC 3.2: rangeAtt = square(saturate(1 - square(distSqr * invRangeSq))).
float rangeAttenuation(float distSqr, float invRangeSq) {
  return square(saturate(1.0 - square(distSqr * invRangeSq)));
}

// SPEC 3.2 with the factors of SPEC 3.3 (a, b; the CPU applied 3.4's legacy
// inner angle): spotAtt = square(saturate(dot(spotDir, L) * a + b)).
float spotAttenuation(vec3 spotDirection, vec3 L, vec2 factors) {
  return square(saturate(dot(spotDirection, L) * factors.x + factors.y));
}

// SPEC 3.5: lerp(1, mask[c], strength) for a light with channel c >= 0 on an
// object with a shadow mask; 1 otherwise. `mask` is the object's shadow mask
// at this point (all ones where it has none).
float shadowMaskAttenuation(Light light, vec4 mask) {
  if (!SHADOW_MASK || objectData.lightList.z == 0) return 1.0;
  int channel = int(light.spotAngles.z);
  if (channel < 0) return 1.0;
  return mix(1.0, mask[channel], light.spotAngles.w);
}

// SPEC 3.1: finalColor * saturate(dot(N, L)) * shadowMask (albedo applied by the caller).
vec3 directionalLight(Light light, vec3 N, vec4 mask) {
  vec3 L = light.position.xyz;
  return light.color.rgb * (saturate(dot(N, L)) * shadowMaskAttenuation(light, mask));
}

// SPEC 3.2: point and spot lights at camera-relative position p.
vec3 localLight(Light light, vec3 p, vec3 N, vec4 mask) {
  vec3 ray = light.position.xyz - p;
  float distSqr = clampedDistanceSquared(ray);
  vec3 L = ray * inversesqrt(distSqr);
  float attenuation = rangeAttenuation(distSqr, light.color.w) / distSqr;
  if (SPOT_LIGHTS) attenuation *= spotAttenuation(light.spotDirection.xyz, L, light.spotAngles.xy);
  attenuation *= shadowMaskAttenuation(light, mask);
  return light.color.rgb * (saturate(dot(N, L)) * attenuation);
}

// A light of the packed `otherLights` array. In the legacy profile it holds
// directional lights too (w = 0); in srp only point and spot lights.
vec3 packedLight(Light light, vec3 p, vec3 N, vec4 mask) {
  if (DIRECTIONAL_LIGHTS && light.position.w == 0.0) return directionalLight(light, N, mask);
  if (!POINT_LIGHTS && !SPOT_LIGHTS) return vec3(0.0);
  return localLight(light, p, N, mask);
}

#endif
