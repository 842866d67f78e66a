#version 450
#extension GL_GOOGLE_include_directive : require
// The depth-only shadow pass (SPEC 3.9): every object drawn from one view of
// a shadowed light into a 32-bit float depth map, no culling, no depth bias
// (lighting::kShadowCasterState). The object's camera-relative position is
// the forward pass's, operation for operation; the view's transform maps it
// to the map's clip space (lighting::ShadowPassView, x and y to mu and mv in
// [-1, 1], depth z/w in [0, 1]).
#include "admissible.glsl"
#include "object_data.glsl"

layout(std140, LIGHTCTS_BINDING(ShadowPassBlock)) uniform ShadowPassBlock {
  mat4 clipFromCameraRelative;
  vec4 rasterGrid;  // the map's grid for the snapping admissible variants (z = 0: not snapped)
} shadowPass;

layout(location = 0) in vec3 inPosition;

void main() {
  vec4 position = objectData.model * vec4(inPosition, 1.0);
  gl_Position = snappedClipPosition(shadowPass.clipFromCameraRelative * position, shadowPass.rasterGrid,
                                    shadowPass.rasterGrid.z > 0.0);
}
