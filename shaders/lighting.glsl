// The lighting model of SPEC 3, written once. Every stage and every API uses
// these functions: Vulkan consumes the SPIR-V, OpenGL the GLSL that
// SPIRV-Cross makes of it. Nowhere else is a formula of SPEC 3 written for
// the GPU.
#ifndef LIGHTCTS_LIGHTING_GLSL
#define LIGHTCTS_LIGHTING_GLSL

#include "shader_interface.glsl"
#include "admissible.glsl"
#include "light_data.glsl"
#include "cookies.glsl"
#include "shadows.glsl"

// The value of every per-light texture at the point being lit: the cookies
// (SPEC 3.10) and the real-time shadow maps (SPEC 3.9), each looked up once
// per invocation for all lights (cookies.glsl explains why).
struct LightTextures {
  CookieValues cookies;
  ShadowValues shadows;
};
LightTextures lightTexturesAt(vec3 p, vec3 N) { return LightTextures(cookieValuesAt(p), shadowValuesAt(p, N)); }
// Legacy vertex lights: cookies, but no shadow map (the vertex stage reads none).
LightTextures lightTexturesAtVertex(vec3 p) { return LightTextures(cookieValuesAt(p), unshadowed()); }
// What `light`'s cookie and shadow map multiply its attenuation by.
float lightTextureAttenuation(Light light, LightTextures textures) {
  return cookieAttenuation(light, textures.cookies) * shadowMapAttenuation(light, textures.shadows);
}

// Mutant: spot factors for the full cone angle taken as the half angle. The
// shader recovers cosOuter = -b/a and cosInner = cosOuter + 1/a (exact where
// a was not clamped) and doubles both angles: cos(2t) = 2 cos^2(t) - 1.
vec2 fullAngleSpotFactors(vec2 factors) {
  if (factors.x == 0.0) return factors;  // a point light
  float cosOuter = -factors.y / factors.x;
  float cosInner = cosOuter + 1.0 / factors.x;
  float cosOuterFull = 2.0 * cosOuter * cosOuter - 1.0;
  float cosInnerFull = 2.0 * cosInner * cosInner - 1.0;
  float a = 1.0 / max(cosInnerFull - cosOuterFull, 0.001);
  return vec2(a, -cosOuterFull * a);
}

// SPEC 3.5: lerp(1, mask[c], strength) for a light with channel c >= 0 on an
// object with a shadow mask; 1 otherwise. `mask` is the object's shadow mask
// at this point, all ones where it has none: the caller decides (forward from
// the object's flag, deferred from the G-buffer's mask target), so this
// function reads no per-object data. All ones gives exactly 1 (what the
// model's lerp(1, 1, strength) is) whatever rounding mix() would do.
float shadowMaskAttenuation(Light light, vec4 mask) {
  if (!SHADOW_MASK || mask == vec4(1.0)) return 1.0;
  int channel = int(light.spotAngles.z);
  if (channel < 0 || channel >= kShadowSlotBase) return 1.0;  // none, or a real-time shadow slot
  if (MUTANT == MUTANT_SHADOW_MASK_CHANNEL_OFF_BY_ONE) channel = (channel + 1) % 4;
  float strength = MUTANT == MUTANT_SHADOW_STRENGTH_IGNORED ? 1.0 : light.spotAngles.w;
  return mix(1.0, mask[channel], strength);
}

// Mutant: where the absolute-coordinates mutant puts positions, in float32:
// absolute world coordinates (camera-relative + the camera position). The
// model keeps them camera-relative (identity).
vec3 mutantWorldPosition(vec3 cameraRelative) {
  if (MUTANT == MUTANT_ABSOLUTE_COORDINATES) return cameraRelative + frameData.cameraPosition.xyz;
  return cameraRelative;
}

// x rounded to the nearest 16-bit float (ties to even; beyond the largest
// half, infinity), what unpackHalf2x16(packHalf2x16(x)) gives. Written out
// because GLSL 330 (the OpenGL backend) has no packHalf2x16.
float roundThroughHalf(float x) {
  uint bits = floatBitsToUint(x);
  uint sign = bits & 0x80000000u;
  uint magnitude = bits & 0x7fffffffu;
  float a = uintBitsToFloat(magnitude);
  if (a >= 65520.0) magnitude = 0x7f800000u;
  else if (a < 6.103515625e-05) magnitude = floatBitsToUint(roundEven(a * 16777216.0) / 16777216.0);  // subnormal: steps of 2^-24
  else magnitude = (magnitude + 0x0fffu + ((magnitude >> 13) & 1u)) & ~0x1fffu;  // 10 mantissa bits
  return uintBitsToFloat(sign | magnitude);
}

// Mutant: attenuation rounded through a 16-bit float (identity in the model).
float mutantAttenuationPrecision(float attenuation) {
  if (MUTANT == MUTANT_HALF_PRECISION_ATTENUATION) return roundThroughHalf(attenuation);
  return attenuation;
}


// SPEC 3.1-3.2's terms, in the subset of GLSL the reference compiles too.
#define LIGHTCTS_TERM
#define real float
#define real3 vec3
#define MUTANT_ACTIVE(name) (MUTANT == name)
#include "light_terms.glsl"
#undef MUTANT_ACTIVE
#undef real3
#undef real
#undef LIGHTCTS_TERM

// SPEC 3.1: finalColor * saturate(dot(N, L)) * shadowMask, times the cookie
// (SPEC 3.10) and the real-time shadow (SPEC 3.9) (`textures`: every slot's
// value at this point): the radiance the BRDF weighs (addLight); L is
// returned for the specular lobe.
vec3 directionalLight(Light light, vec3 N, vec4 mask, LightTextures textures, out vec3 L) {
  L = light.position.xyz;
  float attenuation = shadowMaskAttenuation(light, mask) * lightTextureAttenuation(light, textures);
  return flushed(directionalRadiance(light.color.rgb, L, attenuation, N));
}

// SPEC 3.2: point and spot lights at camera-relative position p (the
// absolute-coordinates mutant passes absolute ones).
vec3 localLight(Light light, vec3 p, vec3 N, vec4 mask, LightTextures textures, out vec3 L) {
  vec3 position = mutantWorldPosition(light.position.xyz);
  L = towardLocalLight(position, p);
  vec2 factors = light.spotAngles.xy;
  if (MUTANT == MUTANT_FULL_SPOT_ANGLE) factors = fullAngleSpotFactors(factors);
  vec3 spotDirection = MUTANT == MUTANT_SPOT_DIRECTION_FLIPPED ? -light.spotDirection.xyz : light.spotDirection.xyz;
  return flushed(localRadiance(light.color.rgb, position, light.color.w, spotDirection, factors.x, factors.y,
                               shadowMaskAttenuation(light, mask), lightTextureAttenuation(light, textures), p, N));
}

// A light of the packed `otherLights` array. In the legacy profile it holds
// directional lights too (w = 0); in srp only point and spot lights.
vec3 packedLight(Light light, vec3 p, vec3 N, vec4 mask, LightTextures textures, out vec3 L) {
  L = vec3(0.0);
  if (DIRECTIONAL_LIGHTS && light.position.w == 0.0) return directionalLight(light, N, mask, textures, L);
  if (!POINT_LIGHTS && !SPOT_LIGHTS) return vec3(0.0);
  return localLight(light, p, N, mask, textures, L);
}

// --- SPEC 3.8: the custom pipeline's BRDF -------------------------------

const float kMinReflectivity = 0.04;       // oneMinusReflectivity = 0.96 (1 - metallic)
const float kLobeDenominatorOffset = 1.00001;  // d2 = square(nh2 (r2 - 1) + 1.00001)
const float kMinLh2 = 0.1;                 // max(0.1, lh2)
const float kSafeNormalizeFloor = 1.17549435e-38;  // SafeNormalize: max(dot(v, v), FLT_MIN)

// What the BRDF needs at a fragment. Lambert (or SPECULAR_BRDF off):
// diffuse = A and no lobe, SPEC 3.1-3.2 as written.
struct SurfaceBrdf {
  vec3 diffuse;   // multiplies ambient, lightmap and every light's radiance
  vec3 specular;  // F0: multiplies radiance * specularStrength
  float roughness;
  bool lobe;
  vec3 normal;
  vec3 view;      // V
};

// SPEC 3.8's V at the camera-relative p: normalize(cameraPosition - p) =
// normalize(-p); orthographic: the frame's constant opposite of the view
// direction.
vec3 viewDirection(vec3 p) {
  if (frameData.view[opaque(3)] != 0.0) return frameData.view.xyz;
  if (MUTANT == MUTANT_VIEW_ABSOLUTE_COORDINATES) {
    // Mutant: camera - p in absolute float32 coordinates. cameraPosition.w
    // is 1, which the compiler cannot know, so (p + c) - c is not folded.
    vec3 absolute = p + frameData.cameraPosition.xyz;
    return normalize(frameData.cameraPosition.xyz * frameData.cameraPosition.w - absolute);
  }
  return unitVector(-p);
}

// `material`: x metallic, y smoothness, z 1 for srp (GpuObjectBlock::material,
// or the G-buffer's material target on the deferred path).
SurfaceBrdf surfaceBrdf(vec3 albedo, vec4 material, vec3 N, vec3 V) {
  SurfaceBrdf s;
  s.normal = N;
  s.view = V;
  s.lobe = SPECULAR_BRDF && material.z != 0.0;
  if (!s.lobe) {
    s.diffuse = albedo;
    s.specular = vec3(0.0);
    s.roughness = 0.0;
    return s;
  }
  float metallic = material.x;
  float oneMinusReflectivity = (1.0 - kMinReflectivity) * (1.0 - metallic);
  s.diffuse = albedo * oneMinusReflectivity;
  s.specular = MUTANT == MUTANT_F0_ALBEDO_ALWAYS ? albedo : mix(vec3(kMinReflectivity), albedo, metallic);
  s.roughness = square(1.0 - material.y);
  return s;
}

// SPEC 3.8's specularStrength in direction L.
float specularStrength(SurfaceBrdf s, vec3 L) {
  vec3 h = L + s.view;
  vec3 H = h * inverseSqrt(max(dotProduct(h, h), kSafeNormalizeFloor));  // SafeNormalize: L = -V gives 0
  if (MUTANT == MUTANT_HALF_VECTOR_NOT_NORMALISED) H = h;
  float nh2 = square(saturate(dotProduct(s.normal, H)));
  float lh2 = square(saturate(dotProduct(L, H)));
  float r2 = square(s.roughness);
  float offset = MUTANT == MUTANT_D2_WITHOUT_EPSILON ? 1.0 : kLobeDenominatorOffset;
  float d2 = square(nh2 * (r2 - 1.0) + offset);
  float lh2Floor = MUTANT == MUTANT_LH2_NOT_CLAMPED ? lh2 : max(kMinLh2, lh2);
  return quotient(r2, d2 * lh2Floor * (s.roughness * 4.0 + 2.0));
}

// SPEC 3.8's sum, split where the colours factor out: the diffuse colour
// times the sum of radiances (which starts at ambient + lightmap), F0 times
// the sum of radiance * specularStrength. The forward pass sums every light;
// the deferred light pass one.
struct LightSums {
  vec3 radiance;
  vec3 specular;
};

void addLight(inout LightSums sums, SurfaceBrdf s, vec3 radiance, vec3 L) {
  sums.radiance = flushed(sums.radiance + radiance);
  if (s.lobe) sums.specular = flushed(sums.specular + radiance * specularStrength(s, L));
}

// finalColor * saturate(dot(N, L)) * attenuation * directBRDF summed, plus
// diffuse * (ambient + lightmap): SPEC 3 and 3.8.
vec3 brdfColour(SurfaceBrdf s, LightSums sums) {
  vec3 colour = s.diffuse * sums.radiance;
  if (s.lobe) colour += s.specular * sums.specular;
  return colour;
}

#endif
