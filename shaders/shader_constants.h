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
  kConstantCount = 20,
};

// Whether a constant is an int in the GLSL (the mutant and the slot counts);
// every other one is a bool. GLSL has no implicit int-to-bool conversion, so
// the OpenGL backend spells each as its type.
constexpr bool constantIsInteger(std::uint32_t id) {
  return id == kMutant || id == kCookieTextures || id == kCookieCubes || id == kShadowMapTextures ||
         id == kShadowMapCubes;
}

// The value of every constant, in id order (bools as 0/1, as SPIR-V stores
// them in 32 bits): what `frame` uses, or everything for the full shader.
using ConstantValues = std::array<std::int32_t, kConstantCount>;
ConstantValues constantValues(const lighting::ShaderFeatures& features, const ShaderVariant& variant);

}  // namespace shaders
