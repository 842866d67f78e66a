// The clustered mode's light lists (issue 21, shaders/clusters.glsl) as a
// uniform texel buffer of R32UI texels at set 0, binding 2 of the forward
// pipeline. Every forward frame writes it: the frame's lists in the clustered
// mode, one zero texel otherwise, so the binding is always valid (the full
// shader declares it whatever the frame draws). The buffer grows when a
// frame's lists outgrow it, and only then is the descriptor rewritten.
#pragma once

#include "backends/vulkan/gpu_memory.h"
#include "lighting/frame.h"

#include <cstdint>
#include <optional>

namespace backends::vulkan {

constexpr std::uint32_t kClusterListsBinding = 2;

class ClusterLists {
 public:
  static vk::DescriptorSetLayoutBinding layoutBinding();

  explicit ClusterLists(const VulkanDevice& device);

  // Writes `frame`'s texels (lighting::packClusterTexels); throws
  // NotSupportedError past the device's maxTexelBufferElements. True when
  // the buffer was made anew: its descriptor must be written again.
  bool write(const lighting::Frame& frame);
  // Binding 2 of `set`, for updateDescriptorSets while this lives.
  vk::WriteDescriptorSet descriptorWrite(vk::DescriptorSet set) const;

 private:
  void allocate(vk::DeviceSize texels);

  const VulkanDevice& device_;
  std::optional<HostBuffer> buffer_;
  vk::raii::BufferView view_{nullptr};
  vk::BufferView viewHandle_;  // what the descriptor write points at
  vk::DeviceSize capacity_ = 0;  // in texels
};

}  // namespace backends::vulkan
