// Descriptor set 3 of every pipeline that lights: the per-light textures,
// read by the vertex stage (legacy vertex lights: cookies) and the fragment
// stage. Bindings 0-6 are the cookies' (cookie_textures.h,
// shaders/cookies.glsl), 7-13 the real-time shadow maps' (shadow_maps.h,
// shaders/shadows.glsl). One set, written by both owners; each writes only
// its own bindings, both before the first draw.
#pragma once

#include "backends/vulkan/descriptor_sets.h"

#include <cstdint>

namespace backends::vulkan {

constexpr std::uint32_t kLightTextureSetIndex = 3;

// Cookies: block, four 2D slots, two cube slots.
constexpr std::uint32_t kCookieBlockBinding = 0;
constexpr std::uint32_t kFirstCookieTextureBinding = 1;
constexpr std::uint32_t kFirstCookieCubeBinding = 5;
// Shadow maps: block, four 2D slots, two cube slots.
constexpr std::uint32_t kShadowBlockBinding = 7;
constexpr std::uint32_t kFirstShadowMapBinding = 8;
constexpr std::uint32_t kFirstShadowCubeBinding = 12;
constexpr std::uint32_t kLightTextureBindingCount = 14;

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
