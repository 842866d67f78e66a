// The bytes every backend uploads (std140 uniform blocks), built once here so
// Vulkan and OpenGL draw from identical data. The GLSL side of these structs is
// shaders/light_data.glsl; tests/gpu_packing_test.cpp pins every offset to the
// std140 rules.
//
// Positions are relative to the frame's camera: the subtraction happens here
// in double, so a scene 1e6 from the origin reaches float32 as small numbers
// (SPEC 7's far-from-origin cases).
#pragma once

#include "lighting/frame.h"
#include "lighting/light_clusters.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace lighting {

// std140 has no 3-component type of size 12 in arrays; everything is padded to vec4.
struct alignas(16) GpuVec4 {
  float x = 0, y = 0, z = 0, w = 0;
};
struct alignas(16) GpuIVec4 {
  std::int32_t x = 0, y = 0, z = 0, w = 0;
  std::int32_t& operator[](int i) { return i == 0 ? x : i == 1 ? y : i == 2 ? z : w; }
};
struct alignas(16) GpuMat4 {
  float m[16] = {};  // column-major, as GLSL reads a mat4
};

// One light, directional or local (SPEC 3.1-3.3 and the seeds' arrays).
struct GpuLight {
  GpuVec4 position;       // xyz: camera-relative position (local) or L = -direction (directional); w: 1 local, 0 directional
  GpuVec4 color;          // rgb: finalColor = color * intensity; w: invRangeSq (0 for directional)
  GpuVec4 spotDirection;  // xyz: spotDir = -direction; w: the cookie's GpuCookieBlock slot, -1 without one
  GpuVec4 spotAngles;     // x: a, y: b (point lights 0, 1); z: shadow-mask channel 0-3, shadow-map slot + 4, or -1; w: mask strength
};
static_assert(sizeof(GpuLight) == 64);

constexpr int kGpuMaxDirectionalLights = 4;
constexpr int kGpuMaxOtherLights = 64;

// Binding 0: per frame.
struct GpuFrameBlock {
  GpuMat4 viewProjection;  // camera-relative world to clip (x right, y up, depth 0..1)
  GpuVec4 ambient;         // rgb
  GpuIVec4 lightCounts;    // x: directional lights, y: other lights (legacy: every kind), z: 1 for the legacy profile, w: 1 in the clustered mode
  GpuLight directionalLights[kGpuMaxDirectionalLights];
  GpuLight otherLights[kGpuMaxOtherLights];
  // xyz: the camera position rounded to float; w: 1. The model never reads
  // it (positions are camera-relative); only the test-only mutants in
  // absolute coordinates (forward.vert, lighting.glsl) do, and w = 1 is a factor
  // the shader compiler cannot know, so it cannot fold (p + c) - c away.
  GpuVec4 cameraPosition;
  // SPEC 3.8's view vector: xyz the orthographic V (the unit vector opposite
  // the view direction); w 1 for an orthographic camera, 0 for a perspective
  // one, whose V is normalize(-p) of the camera-relative p.
  GpuVec4 view;
  // The clustered mode (lighting/light_clusters.h), zero in the
  // model's modes: how a fragment finds its cluster. The tile from the pixel
  // its clip position (viewProjection's, interpolated from the vertices) is
  // at (API-neutral: neither gl_FragCoord's origin nor the viewport's flip
  // enters), the slice from its view depth dot(p, forward).
  GpuIVec4 clusterGrid;     // x: tiles across, y: tiles down, z: slices, w: tile size in pixels
  GpuVec4 clusterScreen;    // x: image width, y: image height in pixels
  GpuVec4 clusterForward;   // xyz: the camera's forward axis
  GpuVec4 clusterSlicing;   // x: ClusterGrid::sliceScale, y: sliceBias, z: 1 exponential (log of the depth), 0 linear; w: the near depth
  // Always zero: the shaders read every uniform that steers a loop or a
  // branch at this offset from its own, which the shader compiler cannot
  // fold (shaders/light_data.glsl, opaque()).
  GpuIVec4 opaqueZero;
  // Read by the admissible variants alone (shaders/admissible.glsl), never
  // by the model. xy: the image's size in pixels (packFrameBlock); z:
  // 2^subPixelPrecisionBits and w: the framebuffer's y direction against NDC
  // y, +1 on OpenGL and -1 under Vulkan's flipped viewport (the backend
  // fills both: they are the device's and the API's).
  GpuVec4 rasterGrid;
  GpuVec4 filterGrid;  // x: 2^subTexelPrecisionBits (the backend fills it)
};
static_assert(sizeof(GpuFrameBlock) == 4592);

// Binding 1: per object.
struct GpuObjectBlock {
  GpuMat4 model;          // local to camera-relative world: rotation * scale, then translate - camera
  GpuMat4 normalMatrix;   // the rotation R (SPEC 1), upper 3x3 used
  GpuVec4 albedo;         // rgb
  GpuIVec4 lightList;     // x: list count (may exceed 8), y: lightmap present, z: shadow mask present, w: 1 when the list is in use
  GpuIVec4 lightIndices[2];  // the first min(count, 8) packed indices, -1 past the end
  GpuVec4 lightmapTransform; // u = x_local * x + z, v = z_local * y + w (SPEC 3.6)
  GpuVec4 material;       // x: metallic, y: smoothness, z: 1 for the srp BRDF (SPEC 3.8), 0 Lambert
  // x: 1 when every vertex of the object lies in front of the camera this
  // frame (clip w > 0), 0 otherwise: the snapping variants snap only such an
  // object, since a vertex stage snaps before clipping (shaders/admissible.glsl).
  GpuIVec4 raster;
};
static_assert(sizeof(GpuObjectBlock) == 240);

// Vertex data: local position and normal, float32, interleaved.
struct GpuVertex {
  float position[3];
  float normal[3];
};
static_assert(sizeof(GpuVertex) == 24);

// A double matrix rounded once per entry to float, column-major as GLSL reads
// it: every block that carries a matrix packs it through this.
GpuMat4 toGpuMat4(const glm::dmat4& m);

// What the admissible variants read of the device and of the API that draws
// (GpuFrameBlock::rasterGrid's z and w, filterGrid's x): the backend knows
// them, the frame does not.
struct DeviceGrid {
  int subPixelBits = 4;
  int subTexelBits = 4;
  float framebufferYAgainstNdc = 1;  // +1 OpenGL, -1 Vulkan's flipped viewport
};

GpuFrameBlock packFrameBlock(const Frame& frame, const DeviceGrid& grid = {});
// One light as FrameBlock holds it (also the deferred light pass's block).
// `weight`: the light's fade weight (lighting/light_fade.h); it scales
// finalColor in double before the one rounding to float.
GpuLight packGpuLight(const Frame& frame, int sceneLight, double weight);
GpuObjectBlock packObjectBlock(const Frame& frame, int object);
std::vector<GpuVertex> packVertices(const Mesh& mesh);
// The clustered mode's lists as one array of 32-bit unsigned texels (an
// R32UI texel buffer on Vulkan, a texture buffer on OpenGL 3.3): texel c of
// each cluster c (ClusterGrid::clusterIndex) holds (first << 8) | count,
// where `first` is the texel of its first light index; the light indices
// (into FrameBlock.otherLights) follow all the headers. Throws
// std::length_error past 2^24 texels (what `first` can address).
std::vector<std::uint32_t> packClusterTexels(const LightClusters& clusters);
// What a backend uploads for `frame`: its clusters' texels in the clustered
// mode, one zero texel otherwise (the full shader declares the lists
// whatever the frame draws, so the binding must always be valid).
std::vector<std::uint32_t> packFrameClusterTexels(const Frame& frame);
constexpr int kClusterCountBits = 8;  // a cluster lists at most 64 lights (kGpuMaxOtherLights)
std::vector<std::uint32_t> packIndices(const Mesh& mesh);

}  // namespace lighting
