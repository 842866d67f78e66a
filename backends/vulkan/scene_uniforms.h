// The uniforms every pass that draws the scene's objects reads: the frame
// block and one object block per object, at the device's dynamic-offset
// alignment, in host-visible buffers. The forward pass (ForwardUniforms,
// frame_resources.h) and the deferred passes (DeferredUniforms,
// deferred_resources.h) each own one and point the FrameBlock and ObjectBlock
// bindings of their set 0 at it; they add only what their passes read besides.
#pragma once

#include "backends/vulkan/gpu_memory.h"
#include "lighting/frame.h"
#include "lighting/gpu_packing.h"
#include "shaders/shader_interface.h"  // generated from shaders/shader_interface.def

#include <array>
#include <cstdint>

namespace backends::vulkan {

class SceneUniforms {
 public:
  // The FrameBlock and ObjectBlock bindings (shaders/shader_interface.def) of
  // a set 0 layout that holds these uniforms.
  static std::array<vk::DescriptorSetLayoutBinding, 2> layoutBindings();

  SceneUniforms(const VulkanDevice& device, std::size_t objectCapacity);
  SceneUniforms(const SceneUniforms&) = delete;  // the descriptor infos point at the buffers

  std::size_t objectCapacity() const { return objectCapacity_; }
  std::uint32_t objectOffset(std::size_t object) const { return std::uint32_t(object * objectStride_); }
  // The frame block and every object's block of `frame` (lighting/gpu_packing.h).
  void write(const lighting::Frame& frame);
  // The frame block's and the object block's (dynamic offset) bindings of
  // `set`, for updateDescriptorSets while this lives.
  std::array<vk::WriteDescriptorSet, 2> descriptorWrites(vk::DescriptorSet set) const;

 private:
  lighting::DeviceGrid grid_;  // the device's bits; framebuffer y runs against NDC y (the flipped viewport)
  std::size_t objectCapacity_;
  vk::DeviceSize objectStride_;
  HostBuffer frame_;
  HostBuffer objects_;
  vk::DescriptorBufferInfo frameInfo_;
  vk::DescriptorBufferInfo objectInfo_;
};

}  // namespace backends::vulkan
