// The clustered mode's light lists (shaders/clusters.glsl) as a
// uniform texel buffer of R32UI texels, alone in set 2 of the forward
// pipeline, which the pass binds once (set 0 is bound again for every
// object). Every forward frame writes it: the frame's lists in the clustered
// mode, one zero texel otherwise, so the binding is always valid (the full
// shader declares it whatever the frame draws). The buffer grows when a
// frame's lists outgrow it, and only then is the descriptor rewritten.
#pragma once

#include "backends/vulkan/descriptor_set_indices.h"
#include "backends/vulkan/descriptor_sets.h"
#include "backends/vulkan/gpu_memory.h"
#include "lighting/frame.h"
#include "shaders/shader_interface.h"  // generated from shaders/shader_interface.def

#include <cstdint>
#include <optional>

namespace backends::vulkan {

class ClusterLists {
 public:
  static vk::raii::DescriptorSetLayout createSetLayout(const vk::raii::Device& device);

  ClusterLists(const VulkanDevice& device, const vk::raii::DescriptorSetLayout& layout);

  // Writes `frame`'s texels (lighting::packFrameClusterTexels), between
  // submissions (the set is not in use when it moves to a larger buffer);
  // throws NotSupportedError past the device's maxTexelBufferElements.
  void write(const lighting::Frame& frame);
  vk::DescriptorSet set() const { return *descriptors_.sets.front(); }

 private:
  void allocate(vk::DeviceSize texels);

  const VulkanDevice& device_;
  DescriptorSets descriptors_;
  std::optional<HostBuffer> buffer_;
  vk::raii::BufferView view_{nullptr};
  vk::DeviceSize capacity_ = 0;  // in texels
};

}  // namespace backends::vulkan
