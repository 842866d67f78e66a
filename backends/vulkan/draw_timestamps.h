// The device's own time for one draw: three timestamp queries, written at
// the top of the pipe before the shadow-map passes, at the bottom of the pipe
// after them and after the lighting passes, in draw()'s command buffer. The pool is reset in that same command
// buffer (outside dynamic rendering) before the writes, so every draw starts
// from unavailable queries, and read once the draw's fence has signalled: the
// results are then already there, so reading them waits for nothing.
#pragma once

#include "backends/vulkan/vulkan_device.h"

#include <cstdint>

namespace backends::vulkan {

// Whether the device's graphics queue can time a draw: the queue family has
// timestampValidBits > 0 and the device sets timestampComputeAndGraphics.
bool canTimeDraws(const VulkanDevice& device);

// Ticks between two timestamps of `validBits` bits, in milliseconds: the
// difference is taken modulo 2^validBits (a counter that wrapped once between
// the two still gives the right interval) and scaled by `nanosecondsPerTick`
// (VkPhysicalDeviceLimits::timestampPeriod).
double timestampIntervalMilliseconds(std::uint64_t begin, std::uint64_t end, std::uint32_t validBits,
                                     float nanosecondsPerTick);

class DrawTimestamps {
 public:
  // Only for a device where canTimeDraws() holds.
  explicit DrawTimestamps(const VulkanDevice& device);

  // First in the command buffer: resets both queries, writes the first.
  void recordBegin(const vk::raii::CommandBuffer& commands) const;
  // After the shadow-map passes (SPEC 3.9), before the lighting: every draw
  // writes it, maps or not, so all three queries are always available.
  void recordShadowPassesEnd(const vk::raii::CommandBuffer& commands) const;
  // Last in the command buffer, after the rendering has ended.
  void recordEnd(const vk::raii::CommandBuffer& commands) const;
  // After the command buffer's fence has signalled: from the first to the
  // last timestamp (the whole draw), and to the shadow passes' end.
  double milliseconds() const;
  double shadowPassMilliseconds() const;

 private:
  double interval(std::uint32_t toQuery) const;
  vk::raii::QueryPool pool_{nullptr};
  std::uint32_t validBits_;
  float nanosecondsPerTick_;
};

}  // namespace backends::vulkan
