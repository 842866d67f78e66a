#include "backends/vulkan/frame_resources.h"

#include "backends/vulkan/forward_pipeline.h"

#include <algorithm>
#include <array>

namespace backends::vulkan {
namespace {

vk::DeviceSize roundUp(vk::DeviceSize value, vk::DeviceSize alignment) {
  return (value + alignment - 1) / alignment * alignment;
}

}  // namespace

RenderTarget::RenderTarget(const VulkanDevice& device, vk::Extent2D extent)
    : color(device, kColorFormat, extent,
            vk::ImageUsageFlagBits::eColorAttachment | vk::ImageUsageFlagBits::eTransferSrc,
            vk::ImageAspectFlagBits::eColor),
      depth(device, kDepthFormat, extent, vk::ImageUsageFlagBits::eDepthStencilAttachment,
            vk::ImageAspectFlagBits::eDepth),
      staging(device, vk::DeviceSize(extent.width) * extent.height * 4 * sizeof(float),
              vk::BufferUsageFlagBits::eTransferDst) {}

UniformBuffers::UniformBuffers(const VulkanDevice& device, const vk::raii::DescriptorSetLayout& layout,
                               std::size_t objectCapacity)
    : objectCapacity_(std::max<std::size_t>(objectCapacity, 1)),
      objectStride_(roundUp(sizeof(lighting::GpuObjectBlock), device.limits.minUniformBufferOffsetAlignment)),
      frame_(device, sizeof(lighting::GpuFrameBlock), vk::BufferUsageFlagBits::eUniformBuffer),
      objects_(device, objectStride_ * objectCapacity_, vk::BufferUsageFlagBits::eUniformBuffer) {
  const std::array<vk::DescriptorPoolSize, 2> perSet{{{vk::DescriptorType::eUniformBuffer, 1},
                                                      {vk::DescriptorType::eUniformBufferDynamic, 1}}};
  descriptors_ = DescriptorSets(device.device, layout, perSet, 1);
  const vk::DescriptorSet set = *descriptors_.sets.front();

  const vk::DescriptorBufferInfo frameInfo{*frame_.buffer, 0, sizeof(lighting::GpuFrameBlock)};
  const vk::DescriptorBufferInfo objectInfo{*objects_.buffer, 0, sizeof(lighting::GpuObjectBlock)};
  const std::array<vk::WriteDescriptorSet, 2> writes{{
      {.dstSet = set, .dstBinding = 0, .descriptorCount = 1, .descriptorType = vk::DescriptorType::eUniformBuffer,
       .pBufferInfo = &frameInfo},
      {.dstSet = set, .dstBinding = 1, .descriptorCount = 1,
       .descriptorType = vk::DescriptorType::eUniformBufferDynamic, .pBufferInfo = &objectInfo},
  }};
  device.device.updateDescriptorSets(writes, {});
}

}  // namespace backends::vulkan
