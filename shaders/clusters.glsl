// Forward+ (lighting/light_clusters.h bins the lights on the CPU):
// a fragment finds its cluster (screen tile and view-depth slice) and loops
// over that cluster's lights only. The lists are one R32UI texel buffer
// (lighting::packClusterTexels): per cluster a header (first << 8) | count,
// then the light indices into FrameBlock.otherLights, in packed order, so the
// sum runs in the same order as the all-lights loop and only skips lights
// whose range does not reach the fragment (they add exactly 0 there).
// Only forward.frag includes this: set 2 is the deferred passes' G-buffer.
#ifndef LIGHTCTS_CLUSTERS_GLSL
#define LIGHTCTS_CLUSTERS_GLSL

#include "light_data.glsl"

// Vulkan: a uniform texel buffer, set 2 (the forward pass binds it once; the
// deferred passes have their G-buffer there); OpenGL 3.3: a texture
// buffer on the unit the backend gives the sampler.
layout(LIGHTCTS_BINDING(clusterLists)) uniform usamplerBuffer clusterLists;

// The specialised shader knows from its constant; the full shader asks.
bool clusteredLights() { return CLUSTERED_LIGHTS && frameData.lightCounts[opaque(3)] != 0; }

// The cluster of the camera-relative point p, by LightClusters::clusterAt's
// arithmetic in float: the pixel of its clip position (y down from the
// image's top), the slice of its view depth (ClusterGrid::sliceOf).
// `clip` is forward.vert's gl_Position, interpolated (perspective-correct, so
// it is viewProjection * p up to rounding), not viewProjection * p here:
// reading the matrix in this stage makes a lavapipe (Mesa 22.3) frame a fixed
// 70-180 ms longer (measured; the other drivers are not affected), which fits its
// per-bind recompiles (docs/vendors.md, "lavapipe recompiles": the matrix's
// loads change how much inlining removes, and so whether it keeps inlining),
// measured with the steering uniforms read at constant offsets.
int clusterOf(vec4 clip, vec3 p) {
  vec2 ndc = clip.xy / clip.w;
  vec2 pixel = vec2(0.5 + 0.5 * ndc.x, 0.5 - 0.5 * ndc.y) * frameData.clusterScreen.xy;
  ivec4 grid = frameData.clusterGrid;
  ivec2 tile = clamp(ivec2(floor(pixel / float(grid.w))), ivec2(0), grid.xy - 1);
  vec4 slicing = frameData.clusterSlicing;
  float depth = dot(p, frameData.clusterForward.xyz);
  float x = frameData.clusterSlicing[opaque(2)] != 0.0 ? log(max(depth, slicing.w)) : depth;
  int slice = clamp(int(floor(x * slicing.x + slicing.y)), 0, grid.z - 1);
  return (slice * grid.y + tile.y) * grid.x + tile.x;
}

// The cluster's header: x the texel of its first light index, y the count
// (lighting::kClusterCountBits = 8 low bits; the shader cannot include C++).
ivec2 clusterRange(int cluster) {
  uint header = texelFetch(clusterLists, cluster).r;
  return ivec2(int(header >> 8), int(header & 255u));
}

// The packed light index at list texel `texel`.
int clusterLight(int texel) { return int(texelFetch(clusterLists, texel).r); }

#endif
