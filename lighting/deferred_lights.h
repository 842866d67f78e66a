// The deferred path of SPEC 3.7 on the CPU side: what each light pass draws.
// Every kept real-time light (SPEC 5.1's packed lights; per-object lists and
// vertex lights do not apply to deferred) becomes one draw of a closed convex
// volume that encloses everything the light can reach:
//   directional: a full-screen triangle (clip-space positions),
//   point:       an icosphere whose inscribed sphere has the light's range,
//   spot:        a pyramid from the light's position along its direction, as
//                long as the range and as wide as the outer cone; an icosphere
//                when the cone is too wide for a pyramid (half angle >= kWidestPyramidHalfAngleDeg).
// Volumes are drawn back faces only with depth test GREATER_OR_EQUAL against
// the G-buffer depth and no depth writes: a ray through a pixel leaves a convex
// volume exactly once, so each pixel is lit once, also with the camera inside
// the volume (docs/model.md).
#pragma once

#include "lighting/frame.h"
#include "lighting/gpu_packing.h"

#include <vector>

namespace lighting {

constexpr double kWidestPyramidHalfAngleDeg = 75.0;

enum class LightVolumeShape { FullScreen, Icosphere, Pyramid };

// One light pass draw: a triangle list, counter-clockwise seen from outside
// (so culling FRONT faces keeps the back faces), camera-relative world
// positions in float (clip-space positions with w = 1 for FullScreen).
struct LightVolume {
  int light = -1;   // scene light index
  LightVolumeShape shape = LightVolumeShape::FullScreen;
  std::vector<GpuVec4> vertices;  // xyz, w = 1; three per triangle
};

// std140, binding 2 in the light pass: the one light this draw evaluates.
struct GpuDeferredLightBlock {
  GpuLight light;         // exactly as in GpuFrameBlock (packLight)
  GpuIVec4 info;          // x: 1 directional / 0 local; y: 1 full-screen volume (positions are clip space); z, w: unused
};
static_assert(sizeof(GpuDeferredLightBlock) == 80);

// std140, binding 3 in the light and composite passes: per frame.
struct GpuDeferredFrameBlock {
  GpuMat4 inverseViewProjection;  // clip (x right, y up, depth 0..1) to camera-relative world
  GpuIVec4 buffer;                // x: 0 hdr32, 1 hdr16, 2 ldr8 (GLSL: bufferFormat, `buffer` is a keyword)
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
