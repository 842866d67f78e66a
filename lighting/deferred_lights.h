// The deferred path of SPEC 3.7 on the CPU side: what each light pass draws.
// Every kept real-time light (SPEC 5.1's packed lights; per-object lists and
// vertex lights do not apply to deferred) becomes one draw of a closed convex
// volume that encloses everything the light can reach:
//   directional: a full-screen triangle (clip-space positions),
//   point:       an icosphere whose inscribed sphere has the light's range,
//   spot:        a pyramid from the light's position along its direction, as
//                long as the range and as wide as the outer cone; an icosphere
//                when the cone is too wide for a pyramid (half angle >= kWidestPyramidHalfAngleDeg).
// How each volume is rasterised and how the light buffer blends is decided
// here too (lightVolumeRasterState, lightBufferState), as API-neutral data the
// backends only translate: volumes are drawn back faces only with depth test
// GREATER_OR_EQUAL against the G-buffer depth and no depth writes: a ray
// through a pixel leaves a convex volume exactly once, so each pixel is lit
// once, also with the camera inside the volume (docs/model.md).
#pragma once

#include "lighting/frame.h"
#include "lighting/gpu_packing.h"
#include "lighting/raster_state.h"
#include "lighting/scene.h"

#include <vector>

namespace lighting {

constexpr double kWidestPyramidHalfAngleDeg = 75.0;

// The G-buffer (SPEC 3.7), RGBA32F targets in this order: fragment output
// location, colour attachment and texture binding i are target i in both
// backends (shaders/gbuffer.frag writes them, shaders/deferred_data.glsl
// reads them). Material carries SPEC 3.8's metallic and smoothness.
enum class GbufferTarget { Albedo = 0, Normal = 1, Base = 2, Mask = 3, Material = 4 };
constexpr int kGbufferTargetCount = 5;

enum class LightVolumeShape { FullScreen, Icosphere, Pyramid };

// The texture slots one light pass draw looks up: the light's own cookie
// slot (cookieBlockSlot) and real-time shadow slot (shadowBlockSlot), -1 for
// none. The backends specialise each light pass pipeline to them
// (shaders::lightPassConstants), so a light samples its own textures only,
// not every slot the frame uses.
struct LightPassSlots {
  int cookie = -1;
  int shadow = -1;
};

// One light pass draw: a triangle list, counter-clockwise seen from outside
// (so culling FRONT faces keeps the back faces), camera-relative world
// positions in float (clip-space positions with w = 1 for FullScreen).
struct LightVolume {
  int light = -1;   // scene light index
  LightVolumeShape shape = LightVolumeShape::FullScreen;
  std::vector<GpuVec4> vertices;  // xyz, w = 1; three per triangle
  LightPassSlots slots;           // the textures this draw looks up
};

// Which rule the light pass draws volumes by: the model's, or that of the
// point-volume-outside-only mutant (shaders::Mutant::PointVolumeOutsideOnly;
// shaders::volumeRule maps a mutant to this, since lighting knows no shaders).
enum class VolumeRule { Model, OutsideOnlyMutant };

// How the light pass rasterises a volume of `shape`, against the G-buffer
// depth attached read-only (never written):
//   FullScreen: no culling, depth ALWAYS;
//   Icosphere, Pyramid: back faces only (cull FRONT), depth GREATER_OR_EQUAL,
//     depth clamp on, so back faces past the far plane still draw there (at
//     depth 1, where the background's cleared depth passes);
//   the mutant, on icospheres only: front faces (cull BACK) with depth
//     LESS_OR_EQUAL, which draws nothing for a volume around the camera.
RasterState lightVolumeRasterState(LightVolumeShape shape, VolumeRule rule);

// How light draws accumulate in the light buffer (SPEC 3.7): hdr32 and hdr16
// sum c (blend ONE, ONE) from a clear of 0; ldr8 multiplies exp2(-c) (blend
// DST_COLOR, ZERO) from a clear of 1. The clear is the blend's identity.
enum class LightBlend { Add, Multiply };
struct LightBufferState {
  LightBlend blend = LightBlend::Add;
  float clearValue = 0.0f;  // every channel, alpha included
};
LightBufferState lightBufferState(DeferredBuffer buffer);

// std140, binding 2 in the light pass: the one light this draw evaluates.
struct GpuDeferredLightBlock {
  GpuLight light;         // exactly as in GpuFrameBlock (packLight)
  GpuIVec4 info;          // x: 1 directional / 0 local; y: 1 full-screen volume (positions are clip space); z, w: unused
};
static_assert(sizeof(GpuDeferredLightBlock) == 80);

// std140, binding 3 in the light and composite passes: per frame.
struct GpuDeferredFrameBlock {
  GpuMat4 inverseViewProjection;  // clip (x right, y up, depth 0..1) to camera-relative world
  GpuIVec4 buffer;                // x: 0 hdr32, 1 hdr16, 2 ldr8 (GLSL: bufferFormat, `buffer` is a keyword); y: 0, the index the shaders read x at (shaders/deferred_data.glsl)
};
static_assert(sizeof(GpuDeferredFrameBlock) == 80);

// The volumes of every kept light of `frame`, in packed order (directional first).
std::vector<LightVolume> lightVolumes(const Frame& frame);
// The volume of one scene light (kept or not) seen from `frame`'s camera.
LightVolume lightVolume(const Frame& frame, int sceneLight);
// Throws std::logic_error when `sceneLight` is not kept in `frame`.
GpuDeferredLightBlock packDeferredLight(const Frame& frame, int sceneLight);
GpuDeferredFrameBlock packDeferredFrame(const Frame& frame);

}  // namespace lighting
