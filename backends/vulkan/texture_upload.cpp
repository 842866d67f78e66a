#include "backends/vulkan/texture_upload.h"

#include "backends/backend.h"

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace backends::vulkan {
namespace {

constexpr std::uint64_t kNoTimeout = UINT64_MAX;
// The bytes of one texel of the formats this file creates.
vk::DeviceSize texelBytes(vk::Format format) {
  switch (format) {
    case kSampledMapFormat: return 4 * sizeof(float);
    case kCookieFormat: return sizeof(float);
    default: throw std::logic_error("a texture upload to an image of format " + vk::to_string(format));
  }
}

vk::ImageMemoryBarrier2 layoutTransition(const DeviceImage& image, vk::ImageLayout from, vk::ImageLayout to) {
  vk::ImageMemoryBarrier2 barrier{.oldLayout = from,
                                  .newLayout = to,
                                  .image = *image.image,
                                  .subresourceRange = {vk::ImageAspectFlagBits::eColor, 0, 1, 0, image.layers}};
  if (to == vk::ImageLayout::eTransferDstOptimal) {
    // A fresh image: nothing before the copy to wait for.
    barrier.dstStageMask = vk::PipelineStageFlagBits2::eCopy;
    barrier.dstAccessMask = vk::AccessFlagBits2::eTransferWrite;
  } else {
    // The copy's writes become visible to every later fragment-shader read,
    // in this submission or any later one on the queue.
    barrier.srcStageMask = vk::PipelineStageFlagBits2::eCopy;
    barrier.srcAccessMask = vk::AccessFlagBits2::eTransferWrite;
    // The vertex stage too: legacy vertex lights read cookies (cookies.glsl).
    barrier.dstStageMask = vk::PipelineStageFlagBits2::eVertexShader | vk::PipelineStageFlagBits2::eFragmentShader;
    barrier.dstAccessMask = vk::AccessFlagBits2::eShaderSampledRead;
  }
  return barrier;
}

}  // namespace

DeviceImage createSampledMapImage(const VulkanDevice& device, vk::Extent2D extent, vk::Format format) {
  return DeviceImage(device, format, extent,
                     vk::ImageUsageFlagBits::eSampled | vk::ImageUsageFlagBits::eTransferDst,
                     vk::ImageAspectFlagBits::eColor);
}

vk::raii::Sampler createSingleLevelSampler(const vk::raii::Device& device, vk::Filter filter,
                                           vk::SamplerAddressMode address) {
  return vk::raii::Sampler(device, vk::SamplerCreateInfo{.magFilter = filter,
                                                         .minFilter = filter,
                                                         .mipmapMode = vk::SamplerMipmapMode::eNearest,
                                                         .addressModeU = address,
                                                         .addressModeV = address,
                                                         .addressModeW = address,
                                                         .mipLodBias = 0.0f,
                                                         .anisotropyEnable = VK_FALSE,
                                                         .compareEnable = VK_FALSE,
                                                         .minLod = 0.0f,
                                                         .maxLod = 0.0f,
                                                         .unnormalizedCoordinates = VK_FALSE});
}

void requireFilterableFormat(const VulkanDevice& device, vk::Format format, const std::string& use) {
  const vk::FormatProperties properties = device.physical.getFormatProperties(format);
  const vk::FormatFeatureFlags needed =
      vk::FormatFeatureFlagBits::eSampledImage | vk::FormatFeatureFlagBits::eSampledImageFilterLinear;
  if ((properties.optimalTilingFeatures & needed) != needed)
    throw NotSupportedError(device.info.name + " cannot sample " + vk::to_string(format) +
                            " images with optimal tiling and linear filtering (optimalTilingFeatures lacks "
                            "SAMPLED_IMAGE or SAMPLED_IMAGE_FILTER_LINEAR); " + use);
}

DeviceImage createSampledCubeImage(const VulkanDevice& device, std::uint32_t size, vk::Format format) {
  return DeviceImage(device, format, {size, size},
                     vk::ImageUsageFlagBits::eSampled | vk::ImageUsageFlagBits::eTransferDst,
                     vk::ImageAspectFlagBits::eColor, ImageShape::Cube);
}

void uploadTextures(const VulkanDevice& device, std::span<const TextureUpload> uploads) {
  if (uploads.empty()) return;
  // Each image's texels at its own offset, rounded up to a multiple of its
  // texel size, as vkCmdCopyBufferToImage requires (the formats mix: an
  // R32F cookie of an odd texel count may come before an RGBA32F one).
  std::vector<vk::DeviceSize> offsets;
  vk::DeviceSize total = 0;
  for (const TextureUpload& u : uploads) {
    const vk::Extent2D extent = u.image->extent;
    const vk::DeviceSize texel = texelBytes(u.image->format);
    if (u.texels.size_bytes() != vk::DeviceSize(extent.width) * extent.height * u.image->layers * texel)
      throw std::logic_error("a texture upload of " + std::to_string(u.texels.size()) + " floats for a " +
                             std::to_string(extent.width) + " x " + std::to_string(extent.height) + " x " +
                             std::to_string(u.image->layers) + " " + vk::to_string(u.image->format) + " image");
    total = (total + texel - 1) / texel * texel;
    offsets.push_back(total);
    total += u.texels.size_bytes();
  }
  HostBuffer staging(device, total, vk::BufferUsageFlagBits::eTransferSrc);
  for (std::size_t k = 0; k < uploads.size(); ++k) staging.write(uploads[k].texels, offsets[k]);

  const vk::raii::CommandPool pool(device.device,
                                   vk::CommandPoolCreateInfo{.flags = vk::CommandPoolCreateFlagBits::eTransient,
                                                             .queueFamilyIndex = device.queueFamily});
  vk::raii::CommandBuffers buffers(device.device, vk::CommandBufferAllocateInfo{.commandPool = *pool,
                                                                                .level = vk::CommandBufferLevel::ePrimary,
                                                                                .commandBufferCount = 1});
  const vk::raii::CommandBuffer& cb = buffers.front();
  cb.begin(vk::CommandBufferBeginInfo{.flags = vk::CommandBufferUsageFlagBits::eOneTimeSubmit});

  std::vector<vk::ImageMemoryBarrier2> barriers;
  for (const TextureUpload& u : uploads)
    barriers.push_back(layoutTransition(*u.image, vk::ImageLayout::eUndefined, vk::ImageLayout::eTransferDstOptimal));
  cb.pipelineBarrier2(vk::DependencyInfo{.imageMemoryBarrierCount = std::uint32_t(barriers.size()),
                                         .pImageMemoryBarriers = barriers.data()});
  for (std::size_t k = 0; k < uploads.size(); ++k) {
    const vk::Extent2D extent = uploads[k].image->extent;
    const vk::BufferImageCopy region{.bufferOffset = offsets[k],
                                     .bufferRowLength = 0,  // tightly packed
                                     .bufferImageHeight = 0,
                                     .imageSubresource = {vk::ImageAspectFlagBits::eColor, 0, 0,
                                                          uploads[k].image->layers},
                                     .imageOffset = {0, 0, 0},
                                     .imageExtent = {extent.width, extent.height, 1}};
    cb.copyBufferToImage(*staging.buffer, *uploads[k].image->image, vk::ImageLayout::eTransferDstOptimal, region);
  }
  barriers.clear();
  for (const TextureUpload& u : uploads)
    barriers.push_back(
        layoutTransition(*u.image, vk::ImageLayout::eTransferDstOptimal, vk::ImageLayout::eShaderReadOnlyOptimal));
  cb.pipelineBarrier2(vk::DependencyInfo{.imageMemoryBarrierCount = std::uint32_t(barriers.size()),
                                         .pImageMemoryBarriers = barriers.data()});
  cb.end();

  // The staging buffer is coherent and written before the submission, which
  // makes host writes visible to the device by itself.
  const vk::raii::Fence fence(device.device, vk::FenceCreateInfo{});
  const vk::CommandBuffer handle = *cb;
  device.queue.submit(vk::SubmitInfo{.commandBufferCount = 1, .pCommandBuffers = &handle}, *fence);
  if (device.device.waitForFences({*fence}, VK_TRUE, kNoTimeout) != vk::Result::eSuccess)
    throw DriverError("waiting for the Vulkan queue failed while uploading textures");
}

}  // namespace backends::vulkan
