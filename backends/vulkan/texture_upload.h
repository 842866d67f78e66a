// Fills sampled images from the CPU: the texels go through one host-visible
// staging buffer and a one-time command buffer (transfer, then the layout the
// fragment stage samples from), and the call waits for the copy to finish.
// Used for the baked maps (baked_textures.h) and the cookies
// (cookie_textures.h), which change only when the
// scene or its bake does, so a blocking upload costs nothing per frame.
#pragma once

#include "backends/vulkan/gpu_memory.h"

#include <cstdint>
#include <span>
#include <string>

namespace backends::vulkan {

// RGBA32F, the format of the maps (lighting::TexelMap): four floats a texel.
constexpr vk::Format kSampledMapFormat = vk::Format::eR32G32B32A32Sfloat;
// R32F, the format of the cookies (backends/cookie_texels.h): one float a texel.
constexpr vk::Format kCookieFormat = vk::Format::eR32Sfloat;

// A 2D image to sample (one mip level, optimal tiling) of `format`, one of the two above.
DeviceImage createSampledMapImage(const VulkanDevice& device, vk::Extent2D extent,
                                  vk::Format format = kSampledMapFormat);

// Throws NotSupportedError unless the device samples `format` with optimal
// tiling and linear filtering; `use` says what needs it.
void requireFilterableFormat(const VulkanDevice& device, vk::Format format, const std::string& use);

// A sampler of one level read at level 0 (maxLod 0), no anisotropy or
// compare: `filter` both ways, `address` on every axis.
vk::raii::Sampler createSingleLevelSampler(const vk::raii::Device& device, vk::Filter filter,
                                           vk::SamplerAddressMode address);

// A cube of `format` to sample, six square faces of `size`.
DeviceImage createSampledCubeImage(const VulkanDevice& device, std::uint32_t size,
                                   vk::Format format = kSampledMapFormat);

struct TextureUpload {
  const DeviceImage* image = nullptr;  // from createSampled*Image, in the undefined layout
  // width * height texels per layer, row by row from row 0, layer after
  // layer (a cube's faces in its order), as many floats each as the image's
  // format has channels.
  std::span<const float> texels;
};

// Copies every upload into its image and leaves the images in
// eShaderReadOnlyOptimal, visible to the fragment stage of later submissions
// on the device's queue. Returns once the device has finished.
void uploadTextures(const VulkanDevice& device, std::span<const TextureUpload> uploads);

}  // namespace backends::vulkan
