// What a frame draws into and from: the colour and depth targets of the
// scene's image size, the uniform buffers (frame block, and one object block
// per object at the device's dynamic-offset alignment) and the descriptor set
// that points at them. Rebuilt only when the size or the object count grows.
#pragma once

#include "backends/vulkan/descriptor_sets.h"
#include "backends/vulkan/gpu_memory.h"
#include "lighting/gpu_packing.h"

namespace backends::vulkan {

struct RenderTarget {
  RenderTarget(const VulkanDevice& device, vk::Extent2D extent);

  DeviceImage color;
  DeviceImage depth;
  HostBuffer staging;  // the readback lands here, RGBA32F rows, row 0 at the top
};

class UniformBuffers {
 public:
  UniformBuffers(const VulkanDevice& device, const vk::raii::DescriptorSetLayout& layout, std::size_t objectCapacity);

  std::size_t objectCapacity() const { return objectCapacity_; }
  const vk::raii::DescriptorSet& descriptorSet() const { return descriptors_.sets.front(); }
  std::uint32_t objectOffset(std::size_t object) const { return std::uint32_t(object * objectStride_); }
  void write(const lighting::GpuFrameBlock& frame) { frame_.write(std::span(&frame, 1)); }
  void write(std::size_t object, const lighting::GpuObjectBlock& block) {
    objects_.write(std::span(&block, 1), objectOffset(object));
  }

 private:
  std::size_t objectCapacity_;
  vk::DeviceSize objectStride_;
  HostBuffer frame_;
  HostBuffer objects_;
  DescriptorSets descriptors_;  // the one set pointing at the buffers
};

}  // namespace backends::vulkan
