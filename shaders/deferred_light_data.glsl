// The light pass's per-draw block (SPEC 3.7), std140 as
// lighting::GpuDeferredLightBlock (dynamic offset), in set 0 beside
// FrameBlock, whose viewProjection places the volume.
#ifndef LIGHTCTS_DEFERRED_LIGHT_DATA_GLSL
#define LIGHTCTS_DEFERRED_LIGHT_DATA_GLSL

#include "light_data.glsl"

// One per light draw (lighting::GpuDeferredLightBlock).
layout(std140, LIGHTCTS_BINDING(DeferredLightBlock)) uniform DeferredLightBlock {
  Light light[1];  // exactly as in FrameBlock; an array so that it is read at an opaque index (light_data.glsl)
  ivec4 info;   // x: 1 directional / 0 local; y: 1 full-screen volume (positions are clip space)
} deferredLight;

#endif
