// The values of the specialization constants (shaders/shader_interface.def),
// for the C++ side that fills them in (Vulkan specialization info, GL defines).
#pragma once

#include "shaders/embedded_spirv.h"
#include "shaders/shader_variant.h"
#include "lighting/frame.h"

#include <array>
#include <cstdint>

namespace shaders {

// shaders::ConstantId (kDirectionalLights, ..., kConstantCount),
// kConstantIsInteger and kConstantDefaults come from
// shaders/shader_interface.def, through shader_variant.h.
// LIGHT_COOKIE_SLOT and LIGHT_SHADOW_SLOT: every slot in use (their default),
// or none (a deferred light pass whose light has none of that kind).
constexpr std::int32_t kEverySlotInUse = kConstantDefaults[kLightCookieSlot];
static_assert(kConstantDefaults[kLightShadowSlot] == kEverySlotInUse);
constexpr std::int32_t kNoSlot = -2;

// The table's cookie and shadow-map slots are the model's, in count (the
// textures) and in the full shader's constants: one check for both backends.
static_assert(binding::kCookieTexture.count() == lighting::kMaxCookieTextures &&
              kConstantDefaults[kCookieTextures] == lighting::kMaxCookieTextures);
static_assert(binding::kCookieCube.count() == lighting::kMaxCookieCubes &&
              kConstantDefaults[kCookieCubes] == lighting::kMaxCookieCubes);
static_assert(binding::kShadowMap.count() == lighting::kMaxShadowMaps &&
              kConstantDefaults[kShadowMapTextures] == lighting::kMaxShadowMaps);
static_assert(binding::kShadowCube.count() == lighting::kMaxShadowCubes &&
              kConstantDefaults[kShadowMapCubes] == lighting::kMaxShadowCubes);

// Whether a constant is an int in the GLSL (the mutant, the slot counts and slots);
// every other one is a bool. GLSL has no implicit int-to-bool conversion, so
// the OpenGL backend spells each as its type.
constexpr bool constantIsInteger(std::uint32_t id) { return id < kConstantCount && kConstantIsInteger[id]; }

// The value of every constant, in id order (bools as 0/1, as SPIR-V stores
// them in 32 bits): what `frame` uses, or everything for the full shader.
using ConstantValues = std::array<std::int32_t, kConstantCount>;
ConstantValues constantValues(const lighting::ShaderFeatures& features, const ShaderVariant& variant);
// Which build of the stages (shaders/embedded_spirv.h) runs `constants`: the
// admissible variants' where ADMISSIBLE is not 0, the model's otherwise.
ShaderBuild shaderBuildOf(const ConstantValues& constants);

// A deferred light pass draw's constants: the frame's, with its light's
// texture slots (lighting::LightVolume::slots) as the only ones it looks up.
// The full shader keeps every slot.
ConstantValues lightPassConstants(ConstantValues frameConstants, const lighting::LightPassSlots& slots,
                                  const ShaderVariant& variant);

}  // namespace shaders
