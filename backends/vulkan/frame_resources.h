// What a forward frame draws into and from: the colour and depth targets of
// the scene's image size, and the scene's uniforms (scene_uniforms.h) with the
// descriptor set that points at them. Rebuilt only when the size or the
// object count grows.
#pragma once

#include "backends/vulkan/descriptor_sets.h"
#include "backends/vulkan/gpu_memory.h"
#include "backends/vulkan/scene_uniforms.h"

namespace backends::vulkan {

struct RenderTarget {
  RenderTarget(const VulkanDevice& device, vk::Extent2D extent);

  DeviceImage color;
  DeviceImage depth;
  HostBuffer staging;  // the readback lands here, RGBA32F rows, row 0 at the top
};

// Set 0 of the forward pipeline (forward_pipeline.h): the frame and object
// blocks' bindings at the scene's uniforms.
class ForwardUniforms {
 public:
  ForwardUniforms(const VulkanDevice& device, const vk::raii::DescriptorSetLayout& layout, std::size_t objectCapacity);

  SceneUniforms& scene() { return scene_; }
  const SceneUniforms& scene() const { return scene_; }
  const vk::raii::DescriptorSet& descriptorSet() const { return descriptors_.sets.front(); }

 private:
  SceneUniforms scene_;
  DescriptorSets descriptors_;  // the one set pointing at the buffers
};

}  // namespace backends::vulkan
