#include "backends/vulkan/cluster_lists.h"

#include "backends/backend.h"
#include "lighting/gpu_packing.h"
#include "lighting/light_clusters.h"

#include <array>
#include <span>
#include <string>
#include <vector>

namespace backends::vulkan {

vk::raii::DescriptorSetLayout ClusterLists::createSetLayout(const vk::raii::Device& device) {
  const vk::DescriptorSetLayoutBinding binding{.binding = shaders::binding::kClusterLists.binding(),
                                               .descriptorType = vk::DescriptorType::eUniformTexelBuffer,
                                               .descriptorCount = 1,
                                               .stageFlags = vk::ShaderStageFlagBits::eFragment};
  return vk::raii::DescriptorSetLayout(device, vk::DescriptorSetLayoutCreateInfo{.bindingCount = 1, .pBindings = &binding});
}

ClusterLists::ClusterLists(const VulkanDevice& device, const vk::raii::DescriptorSetLayout& layout) : device_(device) {
  const std::array<vk::DescriptorPoolSize, 1> perSet{{{vk::DescriptorType::eUniformTexelBuffer, 1}}};
  descriptors_ = DescriptorSets(device.device, layout, perSet, 1);
  allocate(1);
}

void ClusterLists::write(const lighting::Frame& frame) {
  const std::vector<std::uint32_t> texels = lighting::packFrameClusterTexels(frame);
  const vk::DeviceSize needed = texels.size();
  if (needed > device_.limits.maxTexelBufferElements)
    throw NotSupportedError("the clustered mode's lists are " + std::to_string(needed) +
                            " texels; this device's texel buffers hold " +
                            std::to_string(device_.limits.maxTexelBufferElements) +
                            " (choose larger tiles or fewer slices)");
  if (needed > capacity_) allocate(needed);
  buffer_->write(std::span<const std::uint32_t>(texels));
}

void ClusterLists::allocate(vk::DeviceSize texels) {
  view_ = nullptr;  // before the buffer it views
  buffer_.reset();
  buffer_.emplace(device_, texels * sizeof(std::uint32_t), vk::BufferUsageFlagBits::eUniformTexelBuffer);
  view_ = vk::raii::BufferView(device_.device, vk::BufferViewCreateInfo{.buffer = *buffer_->buffer,
                                                                        .format = vk::Format::eR32Uint,
                                                                        .offset = 0,
                                                                        .range = texels * sizeof(std::uint32_t)});
  const vk::BufferView view = *view_;
  device_.device.updateDescriptorSets(
      {vk::WriteDescriptorSet{.dstSet = set(),
                              .dstBinding = shaders::binding::kClusterLists.binding(),
                              .descriptorCount = 1,
                              .descriptorType = vk::DescriptorType::eUniformTexelBuffer,
                              .pTexelBufferView = &view}},
      {});
  capacity_ = texels;
}

}  // namespace backends::vulkan
