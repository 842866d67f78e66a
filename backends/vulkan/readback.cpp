#include "backends/vulkan/readback.h"

#include <cstring>

namespace backends::vulkan {

void recordReadback(const vk::raii::CommandBuffer& commands, const RenderTarget& target) {
  const vk::ImageMemoryBarrier2 toTransfer{
      .srcStageMask = vk::PipelineStageFlagBits2::eColorAttachmentOutput,
      .srcAccessMask = vk::AccessFlagBits2::eColorAttachmentWrite,
      .dstStageMask = vk::PipelineStageFlagBits2::eCopy,
      .dstAccessMask = vk::AccessFlagBits2::eTransferRead,
      .oldLayout = vk::ImageLayout::eColorAttachmentOptimal,
      .newLayout = vk::ImageLayout::eTransferSrcOptimal,
      .image = *target.color.image,
      .subresourceRange = {vk::ImageAspectFlagBits::eColor, 0, 1, 0, 1},
  };
  commands.pipelineBarrier2(vk::DependencyInfo{.imageMemoryBarrierCount = 1, .pImageMemoryBarriers = &toTransfer});

  const vk::Extent2D extent = target.color.extent;
  const vk::BufferImageCopy region{
      .bufferOffset = 0,
      .bufferRowLength = 0,  // tightly packed
      .bufferImageHeight = 0,
      .imageSubresource = {vk::ImageAspectFlagBits::eColor, 0, 0, 1},
      .imageOffset = {0, 0, 0},
      .imageExtent = {extent.width, extent.height, 1},
  };
  commands.copyImageToBuffer(*target.color.image, vk::ImageLayout::eTransferSrcOptimal, *target.staging.buffer, region);

  const vk::BufferMemoryBarrier2 toHost{
      .srcStageMask = vk::PipelineStageFlagBits2::eCopy,
      .srcAccessMask = vk::AccessFlagBits2::eTransferWrite,
      .dstStageMask = vk::PipelineStageFlagBits2::eHost,
      .dstAccessMask = vk::AccessFlagBits2::eHostRead,
      .buffer = *target.staging.buffer,
      .offset = 0,
      .size = VK_WHOLE_SIZE,
  };
  commands.pipelineBarrier2(vk::DependencyInfo{.bufferMemoryBarrierCount = 1, .pBufferMemoryBarriers = &toHost});
}

imaging::Image stagingToImage(const RenderTarget& target) {
  const vk::Extent2D extent = target.color.extent;
  imaging::Image image(int(extent.width), int(extent.height), 4);
  std::memcpy(image.pixels.data(), target.staging.mapped, image.pixels.size() * sizeof(float));
  return image;
}

}  // namespace backends::vulkan
