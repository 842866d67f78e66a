// The Vulkan backend (SPEC 8 `vulkan`): headless, on any Vulkan 1.3 device.
// draw() records the forward pass into an offscreen RGBA32F colour target
// with a D32 depth buffer and waits for it; readback() copies the colour
// target into a host-visible staging buffer (readback.cpp). Scenes on the
// deferred path (SPEC 3.7) draw the G-buffer, light and composite passes of
// deferred_renderer.h instead, ending in the same colour target. The baked
// maps of a scene are uploaded on its first draw (baked_textures.h).
#pragma once

#include "backends/backend.h"

namespace backends::vulkan {

BackendEntry vulkanBackendEntry();

}  // namespace backends::vulkan
