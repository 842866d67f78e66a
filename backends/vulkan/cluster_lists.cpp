#include "backends/vulkan/cluster_lists.h"

#include "backends/backend.h"
#include "lighting/gpu_packing.h"
#include "lighting/light_clusters.h"

#include <span>
#include <string>
#include <vector>

namespace backends::vulkan {

vk::DescriptorSetLayoutBinding ClusterLists::layoutBinding() {
  return {.binding = kClusterListsBinding, .descriptorType = vk::DescriptorType::eUniformTexelBuffer,
          .descriptorCount = 1, .stageFlags = vk::ShaderStageFlagBits::eFragment};
}

ClusterLists::ClusterLists(const VulkanDevice& device) : device_(device) { allocate(1); }

bool ClusterLists::write(const lighting::Frame& frame) {
  const std::vector<std::uint32_t> texels =
      frame.clusters ? lighting::packClusterTexels(*frame.clusters) : std::vector<std::uint32_t>{0};
  const vk::DeviceSize needed = texels.size();
  if (needed > device_.limits.maxTexelBufferElements)
    throw NotSupportedError("the clustered mode's lists are " + std::to_string(needed) +
                            " texels; this device's texel buffers hold " +
                            std::to_string(device_.limits.maxTexelBufferElements) +
                            " (choose larger tiles or fewer slices)");
  const bool grown = needed > capacity_;
  if (grown) allocate(needed);
  buffer_->write(std::span<const std::uint32_t>(texels));
  return grown;
}

vk::WriteDescriptorSet ClusterLists::descriptorWrite(vk::DescriptorSet set) const {
  return {.dstSet = set, .dstBinding = kClusterListsBinding, .descriptorCount = 1,
          .descriptorType = vk::DescriptorType::eUniformTexelBuffer, .pTexelBufferView = &viewHandle_};
}

void ClusterLists::allocate(vk::DeviceSize texels) {
  view_ = nullptr;  // before the buffer it views
  buffer_.reset();
  buffer_.emplace(device_, texels * sizeof(std::uint32_t), vk::BufferUsageFlagBits::eUniformTexelBuffer);
  view_ = vk::raii::BufferView(device_.device, vk::BufferViewCreateInfo{.buffer = *buffer_->buffer,
                                                                        .format = vk::Format::eR32Uint,
                                                                        .offset = 0,
                                                                        .range = texels * sizeof(std::uint32_t)});
  viewHandle_ = *view_;
  capacity_ = texels;
}

}  // namespace backends::vulkan
