#version 450
#extension GL_GOOGLE_include_directive : require
// Deferred light pass (SPEC 3.7): one draw per kept light, of the light's
// volume (lighting::lightVolumes): camera-relative world positions, or clip
// space for the full-screen triangle of a directional light.
#include "deferred_data.glsl"
#include "deferred_light_data.glsl"

layout(location = 0) in vec4 inPosition;

// The clip position before the viewport, so the fragment stage gets the
// normalised device x, y of its pixel (same name in both stages for GLSL 330).
layout(location = 0) out vec4 vClip;

void main() {
  vec4 clip = deferredLight.info[opaque(1)] == 1 ? inPosition : frameData.viewProjection * inPosition;
  vClip = clip;
  gl_Position = clip;
}
