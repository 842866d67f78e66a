#include "backends/vulkan/light_texture_set.h"

#include <array>

namespace backends::vulkan {

namespace {
bool isBlock(std::uint32_t binding) { return binding == kCookieBlockBinding || binding == kShadowBlockBinding; }
}  // namespace

vk::raii::DescriptorSetLayout createLightTextureSetLayout(const vk::raii::Device& device) {
  const auto stages = vk::ShaderStageFlagBits::eVertex | vk::ShaderStageFlagBits::eFragment;
  std::array<vk::DescriptorSetLayoutBinding, kLightTextureBindingCount> bindings;
  for (std::uint32_t b = 0; b < kLightTextureBindingCount; ++b)
    bindings[b] = {.binding = b,
                   .descriptorType = isBlock(b) ? vk::DescriptorType::eUniformBuffer
                                                : vk::DescriptorType::eCombinedImageSampler,
                   .descriptorCount = 1,
                   .stageFlags = stages};
  return vk::raii::DescriptorSetLayout(
      device, vk::DescriptorSetLayoutCreateInfo{.bindingCount = bindings.size(), .pBindings = bindings.data()});
}

LightTextureSet::LightTextureSet(const vk::raii::Device& device, const vk::raii::DescriptorSetLayout& layout) {
  const std::array<vk::DescriptorPoolSize, 2> perSet{
      {{vk::DescriptorType::eUniformBuffer, 2},
       {vk::DescriptorType::eCombinedImageSampler, kLightTextureBindingCount - 2}}};
  sets_ = DescriptorSets(device, layout, perSet, 1);
}

}  // namespace backends::vulkan
