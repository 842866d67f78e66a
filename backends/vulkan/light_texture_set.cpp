#include "backends/vulkan/light_texture_set.h"

#include <vector>

namespace backends::vulkan {

namespace {

constexpr std::uint32_t samplerCount() {
  std::uint32_t count = 0;
  for (const shaders::binding::Texture& texture : kLightTextures) count += std::uint32_t(texture.count());
  return count;
}

constexpr bool allInTheSet() {
  for (const shaders::binding::UniformBlock& block : kLightTextureBlocks)
    if (block.set != kLightTextureSetIndex) return false;
  for (const shaders::binding::Texture& texture : kLightTextures)
    if (texture.set != kLightTextureSetIndex) return false;
  return true;
}
static_assert(allInTheSet());

}  // namespace

vk::raii::DescriptorSetLayout createLightTextureSetLayout(const vk::raii::Device& device) {
  const auto stages = vk::ShaderStageFlagBits::eVertex | vk::ShaderStageFlagBits::eFragment;
  std::vector<vk::DescriptorSetLayoutBinding> bindings;
  for (const shaders::binding::UniformBlock& block : kLightTextureBlocks)
    bindings.push_back({.binding = block.binding, .descriptorType = vk::DescriptorType::eUniformBuffer,
                        .descriptorCount = 1, .stageFlags = stages});
  for (const shaders::binding::Texture& texture : kLightTextures)
    for (std::size_t i = 0; i < texture.count(); ++i)
      bindings.push_back({.binding = texture.binding(i), .descriptorType = vk::DescriptorType::eCombinedImageSampler,
                          .descriptorCount = 1, .stageFlags = stages});
  return vk::raii::DescriptorSetLayout(
      device, vk::DescriptorSetLayoutCreateInfo{.bindingCount = std::uint32_t(bindings.size()),
                                                .pBindings = bindings.data()});
}

LightTextureSet::LightTextureSet(const vk::raii::Device& device, const vk::raii::DescriptorSetLayout& layout) {
  const std::array<vk::DescriptorPoolSize, 2> perSet{
      {{vk::DescriptorType::eUniformBuffer, std::uint32_t(kLightTextureBlocks.size())},
       {vk::DescriptorType::eCombinedImageSampler, samplerCount()}}};
  sets_ = DescriptorSets(device, layout, perSet, 1);
}

}  // namespace backends::vulkan
