// The deferred path's per-frame block and G-buffer textures (SPEC 3.7), used
// by the light and composite passes; std140 as lighting/deferred_lights.h
// lays it out, at the bindings of shader_interface.def (the textures in set
// 2); OpenGL binds blocks and samplers by name (GLSL 330 has no binding
// qualifiers). The light pass's own block is in deferred_light_data.glsl.
#ifndef LIGHTCTS_DEFERRED_DATA_GLSL
#define LIGHTCTS_DEFERRED_DATA_GLSL

#include "shader_interface.glsl"

// Per frame (lighting::GpuDeferredFrameBlock).
layout(std140, LIGHTCTS_BINDING(DeferredFrameBlock)) uniform DeferredFrameBlock {
  mat4 inverseViewProjection;  // clip (x right, y up, depth 0..1) to camera-relative world
  ivec4 bufferFormat;          // x: 0 hdr32, 1 hdr16, 2 ldr8 (GpuDeferredFrameBlock::buffer; `buffer` is a GLSL keyword); y: 0
} deferredFrame;

const int kBufferHdr16 = 1;
const int kBufferLdr8 = 2;

// The specialised shader knows the buffer from LDR8_BUFFER; the full shader
// (every constant on) asks the frame, at an opaque index as light_data.glsl's
// opaque() reads: bufferFormat.y is 0, and the composite pass has no FrameBlock.
bool ldr8Buffer() {
  return LDR8_BUFFER && deferredFrame.bufferFormat[OPAQUE_UNIFORM_READS ? deferredFrame.bufferFormat.y : 0] == kBufferLdr8;
}

// Whether the light buffer is RGBA16F, for the half-toward-zero admissible
// variant alone: the model leaves the conversion to the attachment.
bool hdr16Buffer() { return deferredFrame.bufferFormat.x == kBufferHdr16; }

// ldr8 stores exp2(-c) and decodes -log2(max(x, 1/255)): the clamp keeps a
// fully dark texel (x = 0) finite; it saturates the light sum at log2(255).
const float kLdr8SmallestDecoded = 1.0 / 255.0;

// The G-buffer, RGBA32F each, read with texelFetch at this fragment's pixel
// (the same API and framebuffer as the G-buffer pass wrote, so the same texel).
layout(LIGHTCTS_BINDING(gbufferAlbedo)) uniform sampler2D gbufferAlbedo;  // rgb albedo; a = 1 drawn, 0 background
layout(LIGHTCTS_BINDING(gbufferNormal)) uniform sampler2D gbufferNormal;  // xyz unit normal; w window depth 0..1
layout(LIGHTCTS_BINDING(gbufferBase)) uniform sampler2D gbufferBase;    // rgb albedo * (ambient + lightmap)
layout(LIGHTCTS_BINDING(gbufferMask)) uniform sampler2D gbufferMask;    // the shadow mask, all ones without one
layout(LIGHTCTS_BINDING(gbufferMaterial)) uniform sampler2D gbufferMaterial;  // x metallic, y smoothness, z 1 srp / 0 Lambert
layout(LIGHTCTS_BINDING(lightBuffer)) uniform sampler2D lightBuffer;    // the light pass's sum (hdr) or product (ldr8)

#endif
