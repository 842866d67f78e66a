// The shadow blocks every backend uploads (SPEC 3.9), std140, built once here
// from the frame's ShadowSlots: the lookup block the lighting shaders read
// (per slot its light's camera-relative clip transform, filter, biases and
// cube depth mapping, and the fade), and per view the transform the
// depth-only shadow pass draws with. Camera-relative, like everything else,
// so a scene far from the origin reaches float32 as small numbers. The GLSL
// side is shaders/shadows.glsl.
#pragma once

#include "lighting/frame.h"
#include "lighting/gpu_packing.h"

#include <vector>

namespace lighting {

enum class GpuShadowKind : int { None = 0, Orthographic = 1, Perspective = 2, Cube = 3 };

struct GpuShadow {
  // Camera-relative p' (w = 1) to the map's clip space: mu = x/w * 0.5 + 0.5,
  // mv = y/w * 0.5 + 0.5, depth = z/w (ShadowView::clipFromCameraRelative).
  // Cube: unused (the direction p' - position picks the face).
  GpuMat4 clipFromCameraRelative;
  GpuVec4 params;  // x: GpuShadowKind, y: ShadowFilter (0 hard, 1 bilinear, 2 tent3x3), z: resolution N, w: strength
  GpuVec4 bias;    // x: depth_bias, y: normal_bias; cube: z = far / (far - near), w = z * near (depth = z - w / major)
  GpuVec4 light;   // xyz: camera-relative position (spot, point) or -direction (directional); w: 1 local, 0 directional
};
static_assert(sizeof(GpuShadow) == 112);

// The 2D slots first (kMaxShadowMaps), then the cube slots (kMaxShadowCubes).
constexpr int kGpuShadowSlots = kMaxShadowMaps + kMaxShadowCubes;
struct GpuShadowBlock {
  GpuShadow shadows[kGpuShadowSlots];
  GpuVec4 fade;  // xyz: the camera's forward axis (view depth = dot(p, forward)); w: shadow_distance S
};
static_assert(sizeof(GpuShadowBlock) == 688);

GpuShadowBlock packShadowBlock(const Frame& frame);

// The packed block slot of a scene light's shadow map, or -1 (what the
// shader's Light carries in spotAngles.z, after the shadow-mask channels).
int shadowBlockSlot(const Frame& frame, int sceneLight);

// One depth-only pass of the shadow pass: which slot (and cube face) it
// fills and the transform it draws with (camera-relative world to the view's
// clip space, the same matrix the lookup of a 2D slot uses).
struct ShadowPassView {
  int slot = 0;   // block slot: 2D maps 0..3, cubes kMaxShadowMaps + c
  int face = 0;   // cube face 0..5 (+X, -X, +Y, -Y, +Z, -Z); 0 for a 2D map
  int resolution = 0;
  GpuMat4 clipFromCameraRelative;
  // Whether the snapping admissible variants may move its vertices: an
  // orthographic view's vertices all have w = 1, so a clipped polygon's
  // vertices move no more than theirs; a perspective view's may lie behind
  // the light, whose moves would move the clipped vertices without bound
  // (shaders/admissible.glsl, snappedClipPosition).
  bool snappable = false;
};
std::vector<ShadowPassView> shadowPassViews(const Frame& frame);

// std140, the depth-only pass's per-view block (shaders/shadow_caster.vert).
struct GpuShadowPassBlock {
  GpuMat4 clipFromCameraRelative;  // ShadowPassView::clipFromCameraRelative
  // The map's grid for the snapping admissible variants, as
  // GpuFrameBlock::rasterGrid: resolution twice, 2^subPixelPrecisionBits
  // (0 where the view is not snappable), +1 (neither backend flips a map's viewport).
  GpuVec4 rasterGrid;
};
static_assert(sizeof(GpuShadowPassBlock) == 80);

// One view's block on a device with `subPixelBits` sub-pixel bits.
GpuShadowPassBlock packShadowPassBlock(const ShadowPassView& view, int subPixelBits);

// GpuLight::spotAngles.z: a mixed light's shadow-mask channel 0..3 (SPEC
// 3.5), a real-time light's shadow block slot + kShadowSlotBase (SPEC 3.9),
// or -1. One light has at most one of the two.
constexpr int kShadowSlotBase = 4;

}  // namespace lighting
