#include "backends/vulkan/frame_resources.h"

#include "backends/vulkan/forward_pipeline.h"

#include <array>

namespace backends::vulkan {

RenderTarget::RenderTarget(const VulkanDevice& device, vk::Extent2D extent)
    : color(device, kColorFormat, extent,
            vk::ImageUsageFlagBits::eColorAttachment | vk::ImageUsageFlagBits::eTransferSrc,
            vk::ImageAspectFlagBits::eColor),
      depth(device, kDepthFormat, extent, vk::ImageUsageFlagBits::eDepthStencilAttachment,
            vk::ImageAspectFlagBits::eDepth),
      staging(device, vk::DeviceSize(extent.width) * extent.height * 4 * sizeof(float),
              vk::BufferUsageFlagBits::eTransferDst) {}

ForwardUniforms::ForwardUniforms(const VulkanDevice& device, const vk::raii::DescriptorSetLayout& layout,
                                 std::size_t objectCapacity)
    : device_(device), scene_(device, objectCapacity), clusters_(device) {
  const std::array<vk::DescriptorPoolSize, 3> perSet{{{vk::DescriptorType::eUniformBuffer, 1},
                                                      {vk::DescriptorType::eUniformBufferDynamic, 1},
                                                      {vk::DescriptorType::eUniformTexelBuffer, 1}}};
  descriptors_ = DescriptorSets(device.device, layout, perSet, 1);
  const vk::DescriptorSet set = *descriptors_.sets.front();
  device.device.updateDescriptorSets(scene_.descriptorWrites(set), {});
  device.device.updateDescriptorSets({clusters_.descriptorWrite(set)}, {});
}

void ForwardUniforms::write(const lighting::Frame& frame) {
  scene_.write(frame);
  // Between frames: the backend waits for every submission, so the set is
  // not in use when its binding 2 moves to a larger buffer.
  if (clusters_.write(frame)) device_.device.updateDescriptorSets({clusters_.descriptorWrite(*descriptors_.sets.front())}, {});
}

}  // namespace backends::vulkan
