#include "backends/vulkan/raster_translation.h"

namespace backends::vulkan {

vk::CullModeFlags toVulkan(lighting::CullMode cull) {
  switch (cull) {
    case lighting::CullMode::None: return vk::CullModeFlagBits::eNone;
    case lighting::CullMode::Front: return vk::CullModeFlagBits::eFront;
    case lighting::CullMode::Back: return vk::CullModeFlagBits::eBack;
  }
  return vk::CullModeFlagBits::eBack;
}

vk::CompareOp toVulkan(lighting::DepthCompare compare) {
  switch (compare) {
    case lighting::DepthCompare::Always: return vk::CompareOp::eAlways;
    case lighting::DepthCompare::Less: return vk::CompareOp::eLess;
    case lighting::DepthCompare::LessOrEqual: return vk::CompareOp::eLessOrEqual;
    case lighting::DepthCompare::GreaterOrEqual: return vk::CompareOp::eGreaterOrEqual;
  }
  return vk::CompareOp::eLess;
}

vk::PipelineRasterizationStateCreateInfo rasterizationInfo(const lighting::RasterState& raster) {
  // depthClamp is enabled on the device whenever it has the feature, and the
  // deferred path (the only user of clamping) refuses a device without it.
  return {.depthClampEnable = raster.depthClamp ? VK_TRUE : VK_FALSE,
          .polygonMode = vk::PolygonMode::eFill,
          .cullMode = toVulkan(raster.cull),
          .frontFace = vk::FrontFace::eCounterClockwise,
          .lineWidth = 1.0f};
}

vk::PipelineDepthStencilStateCreateInfo depthStencilInfo(const lighting::RasterState& raster,
                                                         bool hasDepthAttachment) {
  if (!hasDepthAttachment) return {.depthTestEnable = VK_FALSE, .depthWriteEnable = VK_FALSE};
  return {.depthTestEnable = VK_TRUE,
          .depthWriteEnable = raster.depthWrite ? VK_TRUE : VK_FALSE,
          .depthCompareOp = toVulkan(raster.depthTest)};
}

vk::PipelineColorBlendAttachmentState unblendedAttachment() {
  return {.blendEnable = VK_FALSE, .colorWriteMask = kAllChannels};
}

vk::PipelineColorBlendAttachmentState blendedAttachment(lighting::LightBlend blend) {
  const bool multiply = blend == lighting::LightBlend::Multiply;
  const vk::BlendFactor destination = multiply ? vk::BlendFactor::eZero : vk::BlendFactor::eOne;
  return {.blendEnable = VK_TRUE,
          .srcColorBlendFactor = multiply ? vk::BlendFactor::eDstColor : vk::BlendFactor::eOne,
          .dstColorBlendFactor = destination,
          .colorBlendOp = vk::BlendOp::eAdd,
          .srcAlphaBlendFactor = multiply ? vk::BlendFactor::eDstAlpha : vk::BlendFactor::eOne,
          .dstAlphaBlendFactor = destination,
          .alphaBlendOp = vk::BlendOp::eAdd,
          .colorWriteMask = kAllChannels};
}

}  // namespace backends::vulkan
