// The model's API-neutral pass state (lighting/raster_state.h, and the light
// buffer's blend of lighting/deferred_lights.h) in Vulkan's terms. Nothing is
// decided here: each function is a table from the model's enums to Vulkan's.
#pragma once

#include "backends/vulkan/vulkan_api.h"
#include "lighting/deferred_lights.h"
#include "lighting/raster_state.h"

namespace backends::vulkan {

vk::CullModeFlags toVulkan(lighting::CullMode cull);
vk::CompareOp toVulkan(lighting::DepthCompare compare);

// Front faces counter-clockwise: every pass draws with the flipped viewport
// of scene_pass.h, in which the meshes' counter-clockwise front faces stay
// counter-clockwise (Vulkan decides the winding in framebuffer space).
vk::PipelineRasterizationStateCreateInfo rasterizationInfo(const lighting::RasterState& raster);
// `hasDepthAttachment` false (a pass without depth) turns the test off.
vk::PipelineDepthStencilStateCreateInfo depthStencilInfo(const lighting::RasterState& raster,
                                                         bool hasDepthAttachment);

inline constexpr vk::ColorComponentFlags kAllChannels = vk::ColorComponentFlagBits::eR |
                                                        vk::ColorComponentFlagBits::eG |
                                                        vk::ColorComponentFlagBits::eB | vk::ColorComponentFlagBits::eA;
// An attachment written as the fragment stage outputs it.
vk::PipelineColorBlendAttachmentState unblendedAttachment();
// Add: ONE, ONE; Multiply: DST_COLOR, ZERO (and DST_ALPHA, ZERO for alpha).
vk::PipelineColorBlendAttachmentState blendedAttachment(lighting::LightBlend blend);

}  // namespace backends::vulkan
