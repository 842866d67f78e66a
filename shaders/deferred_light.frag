#version 450
#extension GL_GOOGLE_include_directive : require
// Deferred light pass (SPEC 3.7): one light at the G-buffer's surface. The
// position comes back from the pixel's device x, y and the depth the G-buffer
// stored, through the inverse view-projection; the light is the forward
// path's function from lighting.glsl, unchanged. The blend state adds (hdr)
// or multiplies (ldr8, exp2(-c)) the result into the light buffer.
#include "lighting.glsl"
#include "deferred_data.glsl"
#include "deferred_light_data.glsl"

layout(location = 0) in vec4 vClip;

layout(location = 0) out vec4 outLight;

// The pixel centre's normalised device x, y. gl_FragCoord.xy is the centre
// itself (a single-sample pass interpolates at the centre), whereas vClip,
// interpolated over the snapped volume triangle, is the clip position of a
// point up to a sub-pixel step away (docs/tolerances.md, sub-pixel
// snapping): the G-buffer's depth was snapped once already, and a second,
// independent snapping would move the rebuilt position further. vClip tells
// only which way y runs (Vulkan's framebuffer y goes down, OpenGL's up; NDC y
// is up in both here), from its derivative, which is +-2/height and never
// near 0. Derivatives need every fragment of the quad: called before any
// fragment returns.
vec2 pixelCentreNdc() {
  vec2 size = vec2(textureSize(gbufferAlbedo, 0));
  vec2 ndc = gl_FragCoord.xy / size * 2.0 - 1.0;
  return vec2(ndc.x, dFdy(vClip.y / vClip.w) < 0.0 ? -ndc.y : ndc.y);
}

void main() {
  vec2 ndcXY = pixelCentreNdc();
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 albedo = texelFetch(gbufferAlbedo, pixel, 0);
  if (albedo.a == 0.0) {
    // Background: the blend's identity leaves the buffer as cleared.
    outLight = ldr8Buffer() ? vec4(1.0) : vec4(0.0);
    return;
  }
  vec4 normalDepth = texelFetch(gbufferNormal, pixel, 0);
  vec4 mask = texelFetch(gbufferMask, pixel, 0);
  vec4 material = texelFetch(gbufferMaterial, pixel, 0);
  vec3 ndc = vec3(ndcXY, normalDepth.w);
  vec4 world = deferredFrame.inverseViewProjection * vec4(ndc, 1.0);
  // Camera-relative; absolute in the absolute-coordinates mutant.
  vec3 p = mutantWorldPosition(quotient(world.xyz, world.w));
  vec3 N = normalDepth.xyz;
  // The forward pass's BRDF for this one light (SPEC 3.8).
  SurfaceBrdf surface = surfaceBrdf(albedo.rgb, material, N, viewDirection(p));
  vec3 L;
  // The light's kind and slots steer packedLight: read at an opaque index (light_data.glsl).
  vec3 radiance = packedLight(deferredLight.light[opaque(0)], p, N, mask, lightTexturesAt(p, N), L);
  LightSums sums = LightSums(vec3(0.0), vec3(0.0));
  addLight(sums, surface, radiance, L);
  vec3 c = brdfColour(surface, sums);
  outLight = ldr8Buffer() ? vec4(power2(-c), 1.0) : vec4(hdr16Buffer() ? halfTowardZero(c) : c, 1.0);
}
