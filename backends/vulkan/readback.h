// The Vulkan readback: the colour target, left in COLOR_ATTACHMENT_OPTIMAL by
// the forward pass, is copied into the target's host-visible staging buffer
// and turned into an imaging::Image. The viewport flip of the forward pass
// already put NDC y = +1 at framebuffer row 0, so rows copy straight: row 0 is
// the top of the image (SPEC 1).
#pragma once

#include "backends/vulkan/frame_resources.h"
#include "imaging/image.h"

namespace backends::vulkan {

// Records the layout transition, the copy and the barrier that makes the
// copy visible to the host.
void recordReadback(const vk::raii::CommandBuffer& commands, const RenderTarget& target);

// After the recorded commands completed: the staging buffer as an RGBA image.
imaging::Image stagingToImage(const RenderTarget& target);

}  // namespace backends::vulkan
