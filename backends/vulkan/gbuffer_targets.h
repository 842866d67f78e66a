// What the deferred path (SPEC 3.7) draws into besides the output colour
// image of frame_resources.h: the RGBA32F G-buffer images of
// lighting::GbufferTarget (albedo, normal with the window depth in w, base,
// shadow mask, material), their D32 depth, and
// the light buffer in the scene's `deferred_buffer` format. Every colour
// image is also sampled by a later pass. Rebuilt when the size or the light
// buffer's format changes.
#pragma once

#include "backends/vulkan/gpu_memory.h"
#include "lighting/deferred_lights.h"
#include "lighting/scene.h"

#include <array>

namespace backends::vulkan {

constexpr vk::Format kGBufferFormat = vk::Format::eR32G32B32A32Sfloat;
constexpr std::size_t kGBufferImageCount = lighting::kGbufferTargetCount;  // lighting::GbufferTarget order

// hdr32: RGBA32F, hdr16: RGBA16F, ldr8: RGBA8 UNORM.
vk::Format lightBufferFormat(lighting::DeferredBuffer buffer);

// Throws NotSupportedError, naming the format and the missing feature, when
// the device cannot render and sample the G-buffer format or blend into and
// sample the light buffer's format (optimal tiling).
void requireDeferredFormats(const VulkanDevice& device, lighting::DeferredBuffer buffer);

struct GBufferTargets {
  GBufferTargets(const VulkanDevice& device, vk::Extent2D extent, lighting::DeferredBuffer buffer);

  bool fits(vk::Extent2D size, lighting::DeferredBuffer buffer) const {
    return extent == size && lightBufferKind == buffer;
  }

  vk::Extent2D extent;
  lighting::DeferredBuffer lightBufferKind;
  std::array<DeviceImage, kGBufferImageCount> gbuffer;
  DeviceImage depth;
  DeviceImage lightBuffer;
};

}  // namespace backends::vulkan
