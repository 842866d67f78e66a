#include "backends/vulkan/gbuffer_targets.h"

#include "backends/vulkan/forward_pipeline.h"
#include "lighting/scene_words.h"

#include <string>

namespace backends::vulkan {
namespace {

void requireFeatures(const VulkanDevice& device, vk::Format format, vk::FormatFeatureFlags needed,
                     const std::string& what, const std::string& featureNames) {
  const vk::FormatFeatureFlags has = device.physical.getFormatProperties(format).optimalTilingFeatures;
  if ((has & needed) != needed)
    throw NotSupportedError(device.info.name + " cannot use " + vk::to_string(format) + " for " + what +
                            " (needs " + featureNames + " with optimal tiling)");
}

DeviceImage colorImage(const VulkanDevice& device, vk::Format format, vk::Extent2D extent) {
  return DeviceImage(device, format, extent,
                     vk::ImageUsageFlagBits::eColorAttachment | vk::ImageUsageFlagBits::eSampled,
                     vk::ImageAspectFlagBits::eColor);
}

}  // namespace

vk::Format lightBufferFormat(lighting::DeferredBuffer buffer) {
  switch (buffer) {
    case lighting::DeferredBuffer::Hdr32: return vk::Format::eR32G32B32A32Sfloat;
    case lighting::DeferredBuffer::Hdr16: return vk::Format::eR16G16B16A16Sfloat;
    case lighting::DeferredBuffer::Ldr8: return vk::Format::eR8G8B8A8Unorm;
  }
  return vk::Format::eUndefined;
}

void requireDeferredFormats(const VulkanDevice& device, lighting::DeferredBuffer buffer) {
  // The light volumes rely on depth clamp: without it a volume reaching past
  // the far plane loses its back faces there, and surfaces inside it go unlit
  // (docs/model.md). That is a missing feature, never a wrong picture.
  if (!device.depthClamp)
    throw NotSupportedError("the deferred path needs the depthClamp device feature, which this device lacks");
  const std::uint32_t attachments = device.physical.getProperties().limits.maxColorAttachments;
  if (attachments < kGBufferImageCount)
    throw NotSupportedError("the deferred path draws " + std::to_string(kGBufferImageCount) +
                            " G-buffer targets at once; this device allows " + std::to_string(attachments) +
                            " colour attachments");
  using F = vk::FormatFeatureFlagBits;
  requireFeatures(device, kGBufferFormat, F::eColorAttachment | F::eSampledImage, "the deferred G-buffer",
                  "COLOR_ATTACHMENT and SAMPLED_IMAGE");
  requireFeatures(device, kDepthFormat, F::eDepthStencilAttachment, "the deferred G-buffer depth",
                  "DEPTH_STENCIL_ATTACHMENT");
  requireFeatures(device, lightBufferFormat(buffer), F::eColorAttachment | F::eColorAttachmentBlend | F::eSampledImage,
                  "the " + std::string(lighting::deferredBufferName(buffer)) + " light buffer",
                  "COLOR_ATTACHMENT_BLEND and SAMPLED_IMAGE");
}

GBufferTargets::GBufferTargets(const VulkanDevice& device, vk::Extent2D size, lighting::DeferredBuffer buffer)
    : extent(size),
      lightBufferKind(buffer),
      gbuffer{colorImage(device, kGBufferFormat, size), colorImage(device, kGBufferFormat, size),
              colorImage(device, kGBufferFormat, size), colorImage(device, kGBufferFormat, size),
              colorImage(device, kGBufferFormat, size)},
      depth(device, kDepthFormat, size, vk::ImageUsageFlagBits::eDepthStencilAttachment, vk::ImageAspectFlagBits::eDepth),
      lightBuffer(colorImage(device, lightBufferFormat(buffer), size)) {}

}  // namespace backends::vulkan
