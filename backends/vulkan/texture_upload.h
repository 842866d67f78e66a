// Fills sampled images from the CPU: the texels go through one host-visible
// staging buffer and a one-time command buffer (transfer, then the layout the
// fragment stage samples from), and the call waits for the copy to finish.
// Used for the baked maps (baked_textures.h), which change only when the
// scene or its bake does, so a blocking upload costs nothing per frame.
#pragma once

#include "backends/vulkan/gpu_memory.h"

#include <span>

namespace backends::vulkan {

// RGBA32F, the format of the maps (lighting::TexelMap): four floats a texel.
constexpr vk::Format kSampledMapFormat = vk::Format::eR32G32B32A32Sfloat;

// A 2D image to sample (one mip level, optimal tiling) of kSampledMapFormat.
DeviceImage createSampledMapImage(const VulkanDevice& device, vk::Extent2D extent);

struct TextureUpload {
  const DeviceImage* image = nullptr;  // from createSampledMapImage, in the undefined layout
  // width * height texels, row by row from row 0, four floats each.
  std::span<const float> texels;
};

// Copies every upload into its image and leaves the images in
// eShaderReadOnlyOptimal, visible to the fragment stage of later submissions
// on the device's queue. Returns once the device has finished.
void uploadTextures(const VulkanDevice& device, std::span<const TextureUpload> uploads);

}  // namespace backends::vulkan
