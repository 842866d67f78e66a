// Light cookies (SPEC 3.10) on the GPU: where a point looks up each slot's
// cookie and the bilinear sample at level 0. The CPU decided everything
// else (lighting/cookie_packing.h): which slot each kept light's cookie has,
// and per slot the affine map from the camera-relative p the shaders see to
// the light's cookie space, so the lookup is one matrix product and the step
// of SPEC 3.10 for its kind. The double-precision copy is lighting/cookie.cpp.
//
// Each texture is its own sampler, not an array: GLSL 330 (the OpenGL
// backend, which binds them by name) indexes sampler arrays only with
// constants. The 2D samplers repeat (directional) or clamp to edge (spot) as
// the backend sets them up per slot; the cubes are seamless (Vulkan always,
// OpenGL with GL_TEXTURE_CUBE_MAP_SEAMLESS). Every texture holds the cookie's
// value (alpha, or the first channel) in r.
#ifndef LIGHTCTS_COOKIES_GLSL
#define LIGHTCTS_COOKIES_GLSL

#include "shader_interface.glsl"
#include "admissible.glsl"
#include "light_data.glsl"

// lighting::GpuCookie, std140.
struct Cookie {
  mat4 toCookie;  // camera-relative p (w = 1) to directional (u, v, 0, 1), spot (q, 1), point (p - position, 1)
  vec4 params;    // x: kind (kCookie*), y: spot 0.5 / tan(spot_angle / 2), z: texture index of its kind
};

// lighting::GpuCookieBlock: the four 2D slots, then the two cube slots.
layout(std140, LIGHTCTS_BINDING(CookieBlock)) uniform CookieBlock {
  Cookie cookies[6];
} cookieData;

layout(LIGHTCTS_BINDING(cookieTexture0)) uniform sampler2D cookieTexture0;
layout(LIGHTCTS_BINDING(cookieTexture1)) uniform sampler2D cookieTexture1;
layout(LIGHTCTS_BINDING(cookieTexture2)) uniform sampler2D cookieTexture2;
layout(LIGHTCTS_BINDING(cookieTexture3)) uniform sampler2D cookieTexture3;
layout(LIGHTCTS_BINDING(cookieCube0)) uniform samplerCube cookieCube0;
layout(LIGHTCTS_BINDING(cookieCube1)) uniform samplerCube cookieCube1;

const int kCookieNone = 0;  // lighting::GpuCookieKind
const int kCookieDirectional = 1;
const int kCookieSpot = 2;
const int kCookiePoint = 3;
const int kCookieSlots = 6;

// Every slot's cookie value at one point. A shader looks each slot in use up
// once per invocation (cookieValuesAt) and each light reads its slot's
// (cookieAttenuation), rather than each light sampling: a light cannot pick
// its sampler by index (GLSL 330), and a chain of the six samplers per light
// costs every light six samples on a device that runs both sides of a
// uniform branch (llvmpipe, measured: 9x the frame time of the 64-light
// benchmark field with five cookies).
struct CookieValues {
  float slot[6];
};

// SPEC 3.10 for a 2D slot (directional: repeat; spot: q.z <= 0 gives 0, then
// the projection, clamped to edge by the sampler); mip level 0 only.
float textureCookieValue(Cookie cookie, sampler2D image, vec3 p) {
  int kind = int(cookie.params.x);
  if (kind == kCookieNone) return 1.0;
  vec3 q = (cookie.toCookie * vec4(p, 1.0)).xyz;
  vec2 uv;
  if (kind == kCookieSpot) {
    // The backward cone: q.z <= 0 gives 0, not the mirrored projection.
    if (q.z <= 0.0) return 0.0;
    uv = 0.5 + q.xy * quotient(cookie.params.y, q.z);
  } else {
    uv = q.xy;  // tiled: the sampler repeats
    if (MUTANT == MUTANT_DIRECTIONAL_COOKIE_CLAMPED) {
      // Mutant: clamp to edge instead (half a texel in from each border).
      vec2 halfTexel = 0.5 / vec2(textureSize(image, 0));
      uv = clamp(uv, halfTexel, 1.0 - halfTexel);
    }
  }
  if (MUTANT == MUTANT_COOKIE_V_FLIPPED) uv.y = 1.0 - uv.y;
  return filteredTexel(image, uv, kind == kCookieDirectional, frameData.filterGrid.x).r;
}

// SPEC 3.10 for a cube slot: the direction p - position, seamless.
float cubeCookieValue(Cookie cookie, samplerCube image, vec3 p) {
  if (int(cookie.params.x) == kCookieNone) return 1.0;
  vec3 q = (cookie.toCookie * vec4(p, 1.0)).xyz;
  // Mutant: the cube turned 90 degrees about the light's y axis.
  if (MUTANT == MUTANT_CUBE_COOKIE_ROTATED_90) q = vec3(q.z, q.y, -q.x);
  return textureLod(image, q, 0.0).r;
}

// Whether slot s is looked up: every slot in use, or a light pass's light's own.
bool cookieSlotLookedUp(int s) { return LIGHT_COOKIE_SLOT == -1 || LIGHT_COOKIE_SLOT == s; }

// Every slot's value at the camera-relative p; all ones without COOKIES.
CookieValues cookieValuesAt(vec3 p) {
  CookieValues values;
  for (int s = 0; s < kCookieSlots; ++s) values.slot[s] = 1.0;
  if (!COOKIES) return values;
  // Only the slots in use (the constants; llvmpipe and lavapipe would run a
  // branch on the slot's kind for every slot, both sides); each slot's kind
  // steers the lookup, so it is read at an opaque index (light_data.glsl).
  if (COOKIE_TEXTURES > 0 && cookieSlotLookedUp(0)) values.slot[0] = textureCookieValue(cookieData.cookies[opaque(0)], cookieTexture0, p);
  if (COOKIE_TEXTURES > 1 && cookieSlotLookedUp(1)) values.slot[1] = textureCookieValue(cookieData.cookies[opaque(1)], cookieTexture1, p);
  if (COOKIE_TEXTURES > 2 && cookieSlotLookedUp(2)) values.slot[2] = textureCookieValue(cookieData.cookies[opaque(2)], cookieTexture2, p);
  if (COOKIE_TEXTURES > 3 && cookieSlotLookedUp(3)) values.slot[3] = textureCookieValue(cookieData.cookies[opaque(3)], cookieTexture3, p);
  if (COOKIE_CUBES > 0 && cookieSlotLookedUp(4)) values.slot[4] = cubeCookieValue(cookieData.cookies[opaque(4)], cookieCube0, p);
  if (COOKIE_CUBES > 1 && cookieSlotLookedUp(5)) values.slot[5] = cubeCookieValue(cookieData.cookies[opaque(5)], cookieCube1, p);
  return values;
}

// SPEC 3.10: the value `light`'s cookie multiplies its attenuation by, from
// the values looked up at the point being lit; 1 for a light without one
// (spotDirection.w < 0). Picked by comparing with each constant slot, as
// shadowMapAttenuation does (shadows.glsl says why).
float cookieAttenuation(Light light, CookieValues values) {
  if (!COOKIES) return 1.0;
  int slot = int(light.spotDirection.w);
  float value = 1.0;
  for (int s = 0; s < kCookieSlots; ++s) value = slot == s ? values.slot[s] : value;
  return value;
}

#endif
