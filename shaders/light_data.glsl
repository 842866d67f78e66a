// The uniform blocks, std140, exactly as lighting/gpu_packing.h lays them out
// (lighting/tests/gpu_packing_test.cpp pins the offsets). Positions are
// relative to the camera: the CPU subtracted the camera position in double.
#ifndef LIGHTCTS_LIGHT_DATA_GLSL
#define LIGHTCTS_LIGHT_DATA_GLSL

#include "shader_interface.glsl"

struct Light {
  vec4 position;       // xyz: camera-relative position, or L = -direction; w: 1 local, 0 directional
  vec4 color;          // rgb: finalColor; w: invRangeSq
  vec4 spotDirection;  // xyz: spotDir = -direction; w: cookie slot in CookieBlock, or -1
  vec4 spotAngles;     // x: a, y: b (point: 0, 1); z: shadow-mask channel 0-3, shadow-map slot + 4 (shadows.glsl), or -1; w: mask strength
};

layout(std140, LIGHTCTS_BINDING(FrameBlock)) uniform FrameBlock {
  mat4 viewProjection;  // camera-relative world to clip: x right, y up, depth 0..1
  vec4 ambient;
  ivec4 lightCounts;    // x: directional lights, y: other lights, z: 1 for the legacy profile, w: 1 clustered (clusters.glsl)
  Light directionalLights[4];
  Light otherLights[64];
  vec4 cameraPosition;  // xyz: the camera position in float, w: 1; read only by the absolute-coordinates mutants
  vec4 view;            // SPEC 3.8: xyz the orthographic V; w 1 orthographic, 0 perspective (V = normalize(-p))
  // The clustered mode (clusters.glsl); zero in the model's modes.
  ivec4 clusterGrid;    // x: tiles across, y: tiles down, z: slices, w: tile size in pixels
  vec4 clusterScreen;   // xy: the image size in pixels
  vec4 clusterForward;  // xyz: the camera's forward axis
  vec4 clusterSlicing;  // x: slice scale, y: slice bias, z: 1 exponential, 0 linear; w: the near depth
  ivec4 opaqueZero;     // all zero; see opaque() below
  // Read by the admissible variants alone (admissible.glsl), never by the model:
  vec4 rasterGrid;      // xy: the image's size in pixels; z: 2^subPixelPrecisionBits; w: framebuffer y against NDC y (+1 OpenGL, -1 Vulkan)
  vec4 filterGrid;      // x: 2^subTexelPrecisionBits
} frameData;

// `index`, at an offset the shader compiler cannot know: every uniform that
// steers a loop or a branch is read through it (`lightCounts[opaque(1)]`,
// `cookies[opaque(0)]`). lavapipe (Mesa 22.3) folds the values of up to four
// uniforms read at constant offsets into such conditions into the shader and
// compiles it again with LLVM whenever their buffer is bound anew, keeping no
// variant: once per frame for the frame's blocks, once per draw for an
// object's or a deferred light's, tens of milliseconds each (docs/vendors.md,
// "lavapipe recompiles"). Read at opaque(i), a value is still one uniform
// load, but not one it inlines. driver.VulkanRecompiles.* holds the shaders
// to it.
int opaque(int index) { return OPAQUE_UNIFORM_READS ? index + frameData.opaqueZero.x : index; }

// The specialised shader knows this from its constants; the full shader
// (every constant on) asks the data, so it draws any scene.
bool legacyProfile() { return VERTEX_LIGHTS && frameData.lightCounts[opaque(2)] != 0; }

#endif
