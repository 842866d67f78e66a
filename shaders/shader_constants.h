// The specialization-constant ids of shaders/features.glsl, for the C++ side
// that fills them in (Vulkan specialization info, GL defines).
#pragma once

#include "shaders/shader_variant.h"
#include "lighting/frame.h"

#include <array>
#include <cstdint>

namespace shaders {

enum ConstantId : std::uint32_t {
  kDirectionalLights = 0,
  kPointLights = 1,
  kSpotLights = 2,
  kPerObjectLists = 3,
  kVertexLights = 4,
  kShadowMask = 5,
  kAmbient = 6,
  kMutant = 7,
  kLightmap = 8,
  kLdr8Buffer = 9,  // deferred only: the light buffer is ldr8 (SPEC 3.7)
  kSpecularBrdf = 10,  // some material has the srp BRDF (SPEC 3.8)
  kCookies = 11,       // some kept light has a cookie (SPEC 3.10)
  kShadowMaps = 12,    // some kept light has a real-time shadow map (SPEC 3.9)
  kClusteredLights = 13,  // Forward+: the fragment loops over its cluster's lights
  kOpaqueUniformReads = 14,  // steering uniforms read at opaque offsets (light_data.glsl); off only as a driver probe
  kCookieTextures = 15,      // 2D cookie slots in use (the first N), cube slots:
  kCookieCubes = 16,
  kShadowMapTextures = 17,   // 2D shadow-map slots in use, cube slots:
  kShadowMapCubes = 18,
  kShadowTent = 19,          // some 2D shadow-map slot filters tent3x3
  kLightCookieSlot = 20,     // a deferred light pass: its light's cookie slot alone, or kNoSlot;
  kLightShadowSlot = 21,     // its shadow slot alone, or kNoSlot; elsewhere kEverySlotInUse
  kConstantCount = 22,
};
constexpr std::int32_t kEverySlotInUse = -1;  // LIGHT_COOKIE_SLOT, LIGHT_SHADOW_SLOT (features.glsl)
constexpr std::int32_t kNoSlot = -2;

// Whether a constant is an int in the GLSL (the mutant, the slot counts and slots);
// every other one is a bool. GLSL has no implicit int-to-bool conversion, so
// the OpenGL backend spells each as its type.
constexpr bool constantIsInteger(std::uint32_t id) {
  return id == kMutant || id == kCookieTextures || id == kCookieCubes || id == kShadowMapTextures ||
         id == kShadowMapCubes || id == kLightCookieSlot || id == kLightShadowSlot;
}

// The value of every constant, in id order (bools as 0/1, as SPIR-V stores
// them in 32 bits): what `frame` uses, or everything for the full shader.
using ConstantValues = std::array<std::int32_t, kConstantCount>;
ConstantValues constantValues(const lighting::ShaderFeatures& features, const ShaderVariant& variant);
// A deferred light pass draw's constants: the frame's, with its light's
// texture slots (lighting::LightVolume::slots) as the only ones it looks up.
// The full shader keeps every slot.
ConstantValues lightPassConstants(ConstantValues frameConstants, const lighting::LightPassSlots& slots,
                                  const ShaderVariant& variant);

}  // namespace shaders
