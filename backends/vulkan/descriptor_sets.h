// A descriptor pool sized for `count` sets of one layout, and those sets: what
// the uniform buffers, the baked maps and the deferred G-buffer each need.
// The pool is declared first, so the sets (which free themselves,
// eFreeDescriptorSet) go before it.
#pragma once

#include "backends/vulkan/vulkan_api.h"

#include <cstdint>
#include <span>
#include <vector>

namespace backends::vulkan {

struct DescriptorSets {
  DescriptorSets() = default;
  // `perSet`: the descriptors one set of `layout` holds; the pool gets `count` times that.
  DescriptorSets(const vk::raii::Device& device, const vk::raii::DescriptorSetLayout& layout,
                 std::span<const vk::DescriptorPoolSize> perSet, std::uint32_t count);

  vk::raii::DescriptorPool pool{nullptr};
  std::vector<vk::raii::DescriptorSet> sets;
};

}  // namespace backends::vulkan
