// The light pass's per-draw block (SPEC 3.7), std140 as
// lighting::GpuDeferredLightBlock: Vulkan set 0 binding 2 (dynamic offset),
// beside FrameBlock (binding 0) whose viewProjection places the volume.
#ifndef LIGHTCTS_DEFERRED_LIGHT_DATA_GLSL
#define LIGHTCTS_DEFERRED_LIGHT_DATA_GLSL

#include "light_data.glsl"

// One per light draw (lighting::GpuDeferredLightBlock).
layout(std140, set = 0, binding = 2) uniform DeferredLightBlock {
  Light light[1];  // exactly as in FrameBlock; an array so that it is read at an opaque index (light_data.glsl)
  ivec4 info;   // x: 1 directional / 0 local; y: 1 full-screen volume (positions are clip space)
} deferredLight;

#endif
