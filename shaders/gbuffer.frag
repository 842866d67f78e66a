#version 450
#extension GL_GOOGLE_include_directive : require
// Deferred G-buffer pass (SPEC 3.7), after shaders/forward.vert: what the
// light pass needs at each pixel, and the terms that are not real-time
// lights. Nothing here is lit; the light pass reconstructs the position from
// the depth stored in normal.w, so no pass samples the depth attachment.
#include "lighting.glsl"
#include "object_data.glsl"
#include "object_maps.glsl"

// Same names as forward.vert's outputs: GLSL 330 links stages by name.
layout(location = 0) in vec3 vPosition;
layout(location = 1) in vec3 vNormal;
layout(location = 2) in vec3 vVertexLighting;
layout(location = 3) in vec2 vLightmapUv;
layout(location = 4) in vec4 vClip;  // forward.vert's, for the clustered mode; declared so the interfaces match

layout(location = 0) out vec4 outAlbedo;  // rgb albedo, a = 1 (cleared to 0: background)
layout(location = 1) out vec4 outNormal;  // xyz normalize(vNormal), w = window depth
layout(location = 2) out vec4 outBase;    // rgb albedo * (ambient + lightmap)
layout(location = 3) out vec4 outMask;    // the shadow mask, all ones without one
layout(location = 4) out vec4 outMaterial;  // x metallic, y smoothness, z 1 srp / 0 Lambert (SPEC 3.8)

void main() {
  vec3 albedo = objectData.albedo.rgb;
  outAlbedo = vec4(albedo, 1.0);
  vec3 N = unitVector(vNormal);
  outNormal = vec4(N, gl_FragCoord.z);
  // The ambient and baked terms, times the BRDF's diffuse colour (SPEC 3.8;
  // A for Lambert): exactly the forward pass's sums before any light.
  SurfaceBrdf surface = surfaceBrdf(albedo, objectMaterial(), N, vec3(0.0));
  outBase = vec4(surface.diffuse * unlitSums(vLightmapUv).radiance, 1.0);
  outMaterial = objectData.material;
  outMask = objectShadowMask(vLightmapUv);
}
