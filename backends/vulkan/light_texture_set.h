// Descriptor set 3 of every pipeline that lights: the per-light textures,
// read by the vertex stage (legacy vertex lights: cookies) and the fragment
// stage: the cookies' block and slots (cookie_textures.h, shaders/cookies.glsl)
// and the real-time shadow maps' (shadow_maps.h, shaders/shadows.glsl), at
// the bindings of shaders/shader_interface.def. One set, written by both
// owners; each writes only its own bindings, both before the first draw.
#pragma once

#include "backends/vulkan/descriptor_set_indices.h"
#include "backends/vulkan/descriptor_sets.h"
#include "shaders/shader_interface.h"  // generated from shaders/shader_interface.def

#include <array>
#include <cstdint>

namespace backends::vulkan {

// What the set holds: the blocks, then the textures.
inline constexpr std::array kLightTextureBlocks = {shaders::binding::kCookieBlock, shaders::binding::kShadowBlock};
inline constexpr std::array kLightTextures = {shaders::binding::kCookieTexture, shaders::binding::kCookieCube,
                                              shaders::binding::kShadowMap, shaders::binding::kShadowCube};

vk::raii::DescriptorSetLayout createLightTextureSetLayout(const vk::raii::Device& device);

// The one set of that layout the backend binds for every lighting pass.
class LightTextureSet {
 public:
  LightTextureSet(const vk::raii::Device& device, const vk::raii::DescriptorSetLayout& layout);
  vk::DescriptorSet set() const { return *sets_.sets.front(); }

 private:
  DescriptorSets sets_;
};

}  // namespace backends::vulkan
