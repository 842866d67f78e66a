#include "backends/vulkan/scene_uniforms.h"

#include "backends/aligned_stride.h"

#include <algorithm>
#include <span>

namespace backends::vulkan {

std::array<vk::DescriptorSetLayoutBinding, 2> SceneUniforms::layoutBindings() {
  const auto stages = vk::ShaderStageFlagBits::eVertex | vk::ShaderStageFlagBits::eFragment;
  return {{
      {.binding = shaders::binding::kFrameBlock.binding, .descriptorType = vk::DescriptorType::eUniformBuffer,
       .descriptorCount = 1, .stageFlags = stages},
      {.binding = shaders::binding::kObjectBlock.binding, .descriptorType = vk::DescriptorType::eUniformBufferDynamic,
       .descriptorCount = 1, .stageFlags = stages},
  }};
}

SceneUniforms::SceneUniforms(const VulkanDevice& device, std::size_t objectCapacity)
    : grid_{device.info.subPixelPrecisionBits, device.info.subTexelPrecisionBits, -1.0f},
      objectCapacity_(std::max<std::size_t>(objectCapacity, 1)),
      objectStride_(alignedStride(sizeof(lighting::GpuObjectBlock), device.limits.minUniformBufferOffsetAlignment)),
      frame_(device, sizeof(lighting::GpuFrameBlock), vk::BufferUsageFlagBits::eUniformBuffer),
      objects_(device, objectStride_ * objectCapacity_, vk::BufferUsageFlagBits::eUniformBuffer),
      frameInfo_{*frame_.buffer, 0, sizeof(lighting::GpuFrameBlock)},
      objectInfo_{*objects_.buffer, 0, sizeof(lighting::GpuObjectBlock)} {}

void SceneUniforms::write(const lighting::Frame& frame) {
  const lighting::GpuFrameBlock block = lighting::packFrameBlock(frame, grid_);
  frame_.write(std::span(&block, 1));
  for (std::size_t o = 0; o < frame.scene().objects.size(); ++o) {
    const lighting::GpuObjectBlock object = lighting::packObjectBlock(frame, int(o));
    objects_.write(std::span(&object, 1), objectOffset(o));
  }
}

std::array<vk::WriteDescriptorSet, 2> SceneUniforms::descriptorWrites(vk::DescriptorSet set) const {
  return {{
      {.dstSet = set, .dstBinding = shaders::binding::kFrameBlock.binding, .descriptorCount = 1,
       .descriptorType = vk::DescriptorType::eUniformBuffer, .pBufferInfo = &frameInfo_},
      {.dstSet = set, .dstBinding = shaders::binding::kObjectBlock.binding, .descriptorCount = 1,
       .descriptorType = vk::DescriptorType::eUniformBufferDynamic, .pBufferInfo = &objectInfo_},
  }};
}

}  // namespace backends::vulkan
