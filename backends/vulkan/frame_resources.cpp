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
    : scene_(device, objectCapacity) {
  const std::array<vk::DescriptorPoolSize, 2> perSet{{{vk::DescriptorType::eUniformBuffer, 1},
                                                      {vk::DescriptorType::eUniformBufferDynamic, 1}}};
  descriptors_ = DescriptorSets(device.device, layout, perSet, 1);
  device.device.updateDescriptorSets(scene_.descriptorWrites(*descriptors_.sets.front()), {});
}

}  // namespace backends::vulkan
