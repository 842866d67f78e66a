// Real-time shadow maps (SPEC 3.9) on the GPU: the receiver offset, the
// lookup of each slot's map (hard and bilinear by the slot's compare
// sampler, tent3x3 as four bilinear compares) and shadowAtten with its fade.
// The CPU decided everything else (lighting/shadow_packing.h): which slot
// each kept light's map has, and per slot the camera-relative transform to
// the map's clip space, the filter, the biases and the cube's depth mapping.
// The double-precision copy is reference/shadow_maps.cpp.
//
// Every map is its own sampler, as the cookies are (cookies.glsl): GLSL 330
// indexes sampler arrays only with constants, so a shader looks every slot
// up once per invocation (shadowValuesAt) and each light reads its slot's
// value. Each sampler compares LESS_OR_EQUAL (lit when depth(p') <= texel)
// with nearest filtering for `hard` and linear for the others, clamped to
// the edge; the cubes are seamless (Vulkan always, OpenGL with
// GL_TEXTURE_CUBE_MAP_SEAMLESS). Every map has one level: lookups ask for
// level 0 explicitly, so they are the same in any stage and branch.
#ifndef LIGHTCTS_SHADOWS_GLSL
#define LIGHTCTS_SHADOWS_GLSL

#include "shader_interface.glsl"
#include "admissible.glsl"
#include "light_data.glsl"

// lighting::GpuShadow, std140.
struct Shadow {
  mat4 clipFromCameraRelative;  // camera-relative p' to the map's clip space (2D slots)
  vec4 params;  // x: kind (kShadow*), y: filter (kShadowFilter*), z: resolution N, w: shadow_strength
  vec4 bias;    // x: depth_bias, y: normal_bias; cube: z far / (far - near), w z * near
  vec4 light;   // xyz: camera-relative position, or -direction (w = 0)
};

// lighting::GpuShadowBlock: the four 2D slots, then the two cube slots.
layout(std140, LIGHTCTS_BINDING(ShadowBlock)) uniform ShadowBlock {
  Shadow shadows[6];
  vec4 fade;  // xyz: the camera's forward axis; w: shadow_distance S
} shadowData;

layout(LIGHTCTS_BINDING(shadowMap0)) uniform sampler2DShadow shadowMap0;
layout(LIGHTCTS_BINDING(shadowMap1)) uniform sampler2DShadow shadowMap1;
layout(LIGHTCTS_BINDING(shadowMap2)) uniform sampler2DShadow shadowMap2;
layout(LIGHTCTS_BINDING(shadowMap3)) uniform sampler2DShadow shadowMap3;
layout(LIGHTCTS_BINDING(shadowCube0)) uniform samplerCubeShadow shadowCube0;
layout(LIGHTCTS_BINDING(shadowCube1)) uniform samplerCubeShadow shadowCube1;

const int kShadowNone = 0;  // lighting::GpuShadowKind
const int kShadowOrthographic = 1;
const int kShadowPerspective = 2;
const int kShadowCube = 3;
const int kShadowFilterHard = 0;  // lighting::ShadowFilter
const int kShadowFilterBilinear = 1;
const int kShadowFilterTent = 2;
const int kShadowSlots = 6;
const int kShadowSlotBase = 4;  // Light.spotAngles.z: mask channels 0-3, then shadow slots (lighting::kShadowSlotBase)

// Every slot's shadowAtten at one point (SPEC 3.9: s with the slot's
// strength and the fade; 1 where a slot is empty).
struct ShadowValues {
  float slot[6];
};

// SPEC 3.9: p' = p + normal_bias N + depth_bias L, L toward the light at p.
vec3 shadowReceiver(Shadow shadow, vec3 p, vec3 N) {
  vec3 L = shadow.light.w == 0.0 ? shadow.light.xyz : unitVector(shadow.light.xyz - p);
  // Mutants: the depth bias left out; the normal bias along L instead of N.
  float depthBias = MUTANT == MUTANT_SHADOW_DEPTH_BIAS_IGNORED ? 0.0 : shadow.bias.x;
  vec3 normalOffset = MUTANT == MUTANT_SHADOW_NORMAL_BIAS_ALONG_L ? L : N;
  return p + shadow.bias.y * normalOffset + depthBias * L;
}

// One compare at (uv, depth), filtered as the slot's sampler does.
float compareAt(sampler2DShadow map, vec2 uv, float depth) { return textureLod(map, vec3(uv, depth), 0.0); }

// SPEC 3.9's tent3x3 (URP's soft shadows) as four bilinear compares; the
// weights and offsets are SPEC 3.9's, per axis.
float tentCompare(sampler2DShadow map, vec2 uv, float depth, float n) {
  vec2 x = uv * n;
  vec2 c = floor(x + 0.5);
  vec2 o = x - c;
  vec2 w0 = ((o + 0.5) * (o + 0.5) * 0.5 - o) * (4.0 / 9.0);
  vec2 w1 = ((1.5 - o) - 0.5 - min(o, 0.0) * min(o, 0.0)) * (4.0 / 9.0);
  vec2 w2 = ((1.5 + o) - 0.5 - max(o, 0.0) * max(o, 0.0)) * (4.0 / 9.0);
  vec2 w3 = ((o + 0.5) * (o + 0.5) * 0.5) * (4.0 / 9.0);
  vec2 wa = w0 + w1, wb = w2 + w3;
  vec2 a = quotient(c + quotient(w1, wa) - 1.5, n), b = quotient(c + quotient(w3, wb) + 0.5, n);
  return wa.x * wa.y * compareAt(map, vec2(a.x, a.y), depth) + wb.x * wa.y * compareAt(map, vec2(b.x, a.y), depth) +
         wa.x * wb.y * compareAt(map, vec2(a.x, b.y), depth) + wb.x * wb.y * compareAt(map, vec2(b.x, b.y), depth);
}

// SPEC 3.9's s for a 2D slot: outside the map (or behind a spot's apex) 1.
float textureShadowValue(Shadow shadow, sampler2DShadow map, vec3 p, vec3 N) {
  int kind = int(shadow.params.x);
  if (kind == kShadowNone) return 1.0;
  vec4 clip = shadow.clipFromCameraRelative * vec4(shadowReceiver(shadow, p, N), 1.0);
  if (kind == kShadowPerspective && clip.w <= 0.0) return 1.0;
  vec3 m = quotient(clip.xyz, clip.w);
  vec2 uv = m.xy * 0.5 + 0.5;
  float depth = m.z;
  if (uv.x < 0.0 || uv.x > 1.0 || uv.y < 0.0 || uv.y > 1.0 || depth < 0.0 || depth > 1.0) return 1.0;
  float n = shadow.params.z;
  // Mutant: every lookup half a texel off the texel centres.
  if (MUTANT == MUTANT_SHADOW_TEXEL_CENTRES_SHIFTED) uv += 0.5 / n;
  if (SHADOW_TENT && int(shadow.params.y) == kShadowFilterTent) return tentCompare(map, uv, depth, n);
  return compareAt(map, uv, depth);
}

// SPEC 3.9's s for a cube slot: the direction p' - position picks the face
// (its major axis), whose perspective depth is far (z - near) / ((far - near) z).
float cubeShadowValue(Shadow shadow, samplerCubeShadow map, vec3 p, vec3 N) {
  if (int(shadow.params.x) == kShadowNone) return 1.0;
  vec3 d = shadowReceiver(shadow, p, N) - shadow.light.xyz;
  vec3 m = abs(d);
  float depth = shadow.bias.z - quotient(shadow.bias.w, max(m.x, max(m.y, m.z)));
  if (depth < 0.0 || depth > 1.0) return 1.0;
  // Mutant: the face chosen by the wrong axis (x and z exchanged).
  if (MUTANT == MUTANT_CUBE_SHADOW_WRONG_AXIS) d = d.zyx;
  return textureGrad(map, vec4(d, depth), vec3(0.0), vec3(0.0));
}

// SPEC 3.9: fade = saturate((z - 0.8 S) / (0.2 S)), z the view depth; 0 for S = 0.
float shadowFadeAt(vec3 p) {
  float S = shadowData.fade[opaque(3)];
  if (S <= 0.0 || MUTANT == MUTANT_SHADOW_FADE_IGNORED) return 0.0;
  return clamp(quotient(dotProduct(p, shadowData.fade.xyz) - 0.8 * S, 0.2 * S), 0.0, 1.0);
}

// SPEC 3.9: shadowAtten = saturate(lerp(1, s, strength) + fade).
float shadowAttenuation(float s, float strength, float fade) {
  // Mutant: the strength applied as a power of s.
  if (MUTANT == MUTANT_SHADOW_STRENGTH_AS_POWER) return clamp(pow(s, strength) + fade, 0.0, 1.0);
  return clamp(mix(1.0, s, strength) + fade, 0.0, 1.0);
}

// Whether slot s is looked up: every slot in use, or a light pass's light's own.
bool shadowSlotLookedUp(int s) { return LIGHT_SHADOW_SLOT == -1 || LIGHT_SHADOW_SLOT == s; }

// Every slot's shadowAtten at the camera-relative p with unit normal N; all
// ones without SHADOW_MAPS. Per fragment, so a light only picks its slot's.
ShadowValues shadowValuesAt(vec3 p, vec3 N) {
  ShadowValues values;
  for (int s = 0; s < kShadowSlots; ++s) values.slot[s] = 1.0;
  if (!SHADOW_MAPS) return values;
  // Only the slots in use (the constants, as cookies.glsl does); each slot's
  // kind and filter steer the lookup: read at an opaque index (light_data.glsl).
  if (SHADOW_MAP_TEXTURES > 0 && shadowSlotLookedUp(0)) values.slot[0] = textureShadowValue(shadowData.shadows[opaque(0)], shadowMap0, p, N);
  if (SHADOW_MAP_TEXTURES > 1 && shadowSlotLookedUp(1)) values.slot[1] = textureShadowValue(shadowData.shadows[opaque(1)], shadowMap1, p, N);
  if (SHADOW_MAP_TEXTURES > 2 && shadowSlotLookedUp(2)) values.slot[2] = textureShadowValue(shadowData.shadows[opaque(2)], shadowMap2, p, N);
  if (SHADOW_MAP_TEXTURES > 3 && shadowSlotLookedUp(3)) values.slot[3] = textureShadowValue(shadowData.shadows[opaque(3)], shadowMap3, p, N);
  if (SHADOW_MAP_CUBES > 0 && shadowSlotLookedUp(4)) values.slot[4] = cubeShadowValue(shadowData.shadows[opaque(4)], shadowCube0, p, N);
  if (SHADOW_MAP_CUBES > 1 && shadowSlotLookedUp(5)) values.slot[5] = cubeShadowValue(shadowData.shadows[opaque(5)], shadowCube1, p, N);
  float fade = shadowFadeAt(p);
  for (int s = 0; s < kShadowSlots; ++s)
    values.slot[s] = shadowAttenuation(values.slot[s], shadowData.shadows[s].params.w, fade);
  return values;
}

// No real-time shadows (legacy vertex lights: the vertex stage reads no map).
ShadowValues unshadowed() {
  ShadowValues values;
  for (int s = 0; s < kShadowSlots; ++s) values.slot[s] = 1.0;
  return values;
}

// `light`'s shadowAtten (SPEC 3.9) for a light with a shadow slot
// (spotAngles.z >= kShadowSlotBase), else 1. The slot's value is picked by
// comparing with each constant slot, not by indexing the array with the
// light's slot: a dynamic index into a local array is a per-lane gather from
// memory on llvmpipe and lavapipe, which cost the 65-light field with shadows
// as much as the lookups themselves (measured; docs/performance.md).
float shadowMapAttenuation(Light light, ShadowValues values) {
  if (!SHADOW_MAPS) return 1.0;
  int slot = int(light.spotAngles.z) - kShadowSlotBase;
  float attenuation = 1.0;
  for (int s = 0; s < kShadowSlots; ++s) attenuation = slot == s ? values.slot[s] : attenuation;
  return attenuation;
}

#endif
