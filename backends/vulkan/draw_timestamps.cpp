#include "backends/vulkan/draw_timestamps.h"

#include <array>

namespace backends::vulkan {
namespace {

constexpr std::uint32_t kBegin = 0;
constexpr std::uint32_t kShadowPassesEnd = 1;
constexpr std::uint32_t kEnd = 2;
constexpr std::uint32_t kQueryCount = 3;

}  // namespace

bool canTimeDraws(const VulkanDevice& device) {
  return device.timestampValidBits > 0 && device.limits.timestampComputeAndGraphics &&
         device.limits.timestampPeriod > 0.0f;
}

double timestampIntervalMilliseconds(std::uint64_t begin, std::uint64_t end, std::uint32_t validBits,
                                     float nanosecondsPerTick) {
  const std::uint64_t mask = validBits >= 64 ? ~std::uint64_t(0) : (std::uint64_t(1) << validBits) - 1;
  const std::uint64_t ticks = ((end & mask) - (begin & mask)) & mask;
  return double(ticks) * double(nanosecondsPerTick) * 1e-6;
}

DrawTimestamps::DrawTimestamps(const VulkanDevice& device)
    : validBits_(device.timestampValidBits), nanosecondsPerTick_(device.limits.timestampPeriod) {
  pool_ = vk::raii::QueryPool(device.device,
                              vk::QueryPoolCreateInfo{.queryType = vk::QueryType::eTimestamp, .queryCount = kQueryCount});
}

void DrawTimestamps::recordBegin(const vk::raii::CommandBuffer& commands) const {
  commands.resetQueryPool(*pool_, 0, kQueryCount);
  commands.writeTimestamp(vk::PipelineStageFlagBits::eTopOfPipe, *pool_, kBegin);
}

void DrawTimestamps::recordShadowPassesEnd(const vk::raii::CommandBuffer& commands) const {
  commands.writeTimestamp(vk::PipelineStageFlagBits::eBottomOfPipe, *pool_, kShadowPassesEnd);
}

void DrawTimestamps::recordEnd(const vk::raii::CommandBuffer& commands) const {
  commands.writeTimestamp(vk::PipelineStageFlagBits::eBottomOfPipe, *pool_, kEnd);
}

double DrawTimestamps::milliseconds() const { return interval(kEnd); }

double DrawTimestamps::shadowPassMilliseconds() const { return interval(kShadowPassesEnd); }

double DrawTimestamps::interval(std::uint32_t to) const {
  // WAIT costs nothing here: the fence of the command buffer that wrote them
  // has signalled, so every query is available.
  const auto [result, ticks] = pool_.getResults<std::uint64_t>(
      0, kQueryCount, kQueryCount * sizeof(std::uint64_t), sizeof(std::uint64_t),
      vk::QueryResultFlagBits::e64 | vk::QueryResultFlagBits::eWait);
  if (result != vk::Result::eSuccess)
    throw DriverError("reading the draw's timestamp queries returned " + vk::to_string(result));
  return timestampIntervalMilliseconds(ticks[kBegin], ticks[to], validBits_, nanosecondsPerTick_);
}

}  // namespace backends::vulkan
