#version 450
#extension GL_GOOGLE_include_directive : require
// Deferred composite pass (SPEC 3.7): base (ambient and lightmap, times
// albedo) plus the decoded light buffer, into the image the forward path
// renders. Background: base 0 and the buffer's clear value decode to 0.
#include "shader_interface.glsl"
#include "admissible.glsl"
#include "deferred_data.glsl"

layout(location = 0) out vec4 outColor;

vec3 decodeLight(vec3 x) {
  if (!ldr8Buffer()) return x;
  // Mutant: no clamp, so a texel that reached 0 decodes to +infinity.
  if (MUTANT == MUTANT_UNCLAMPED_LDR_DECODE) return -log2(x);
  return -logarithm2(max(x, vec3(kLdr8SmallestDecoded)));
}

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec3 base = texelFetch(gbufferBase, pixel, 0).rgb;
  vec3 light = texelFetch(lightBuffer, pixel, 0).rgb;
  outColor = vec4(base + decodeLight(light), 1.0);
}
