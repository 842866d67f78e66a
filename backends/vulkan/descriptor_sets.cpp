#include "backends/vulkan/descriptor_sets.h"

#include <iterator>

namespace backends::vulkan {

DescriptorSets::DescriptorSets(const vk::raii::Device& device, const vk::raii::DescriptorSetLayout& layout,
                               std::span<const vk::DescriptorPoolSize> perSet, std::uint32_t count) {
  std::vector<vk::DescriptorPoolSize> sizes(perSet.begin(), perSet.end());
  for (vk::DescriptorPoolSize& size : sizes) size.descriptorCount *= count;
  // FreeDescriptorSet: vk::raii::DescriptorSet frees itself when destroyed.
  pool = vk::raii::DescriptorPool(device, vk::DescriptorPoolCreateInfo{
                                              .flags = vk::DescriptorPoolCreateFlagBits::eFreeDescriptorSet,
                                              .maxSets = count,
                                              .poolSizeCount = std::uint32_t(sizes.size()),
                                              .pPoolSizes = sizes.data()});
  const std::vector<vk::DescriptorSetLayout> layouts(count, *layout);
  vk::raii::DescriptorSets allocated(device, vk::DescriptorSetAllocateInfo{.descriptorPool = *pool,
                                                                           .descriptorSetCount = count,
                                                                           .pSetLayouts = layouts.data()});
  sets.assign(std::make_move_iterator(allocated.begin()), std::make_move_iterator(allocated.end()));
}

}  // namespace backends::vulkan
