#version 450
#extension GL_GOOGLE_include_directive : require
// Forward fragment stage: SPEC 3's sum for one fragment, over the lights the
// CPU kept (SPEC 4 and 5): every kept light, or the object's list; in the
// clustered benchmark mode, the fragment's cluster's lights (clusters.glsl).
#include "clusters.glsl"
#include "lighting.glsl"
#include "object_data.glsl"
#include "object_maps.glsl"

layout(location = 0) in vec3 vPosition;
layout(location = 1) in vec3 vNormal;
layout(location = 2) in vec3 vVertexLighting;
layout(location = 3) in vec2 vLightmapUv;
layout(location = 4) in vec4 vClip;

layout(location = 0) out vec4 outColor;

const int kMaxLightsPerObject = 8;
const int kLegacyPixelLights = 4;

void main() {
  vec3 p = vPosition;
  vec3 N = unitVector(vNormal);
  vec4 mask = objectShadowMask(vLightmapUv);
  SurfaceBrdf surface = surfaceBrdf(objectData.albedo.rgb, objectMaterial(), N, viewDirection(p));
  LightSums sums = unlitSums(vLightmapUv);
  LightTextures textures = lightTexturesAt(p, N);  // SPEC 3.10 and 3.9, once for every light
  vec3 L;
  // srp keeps directional lights apart and applies them to every object; the
  // legacy profile packs them with the others.
  // Each count is read once, before its loop: read at an opaque offset
  // (light_data.glsl), the load is not one a compiler hoists out of the loop.
  if (DIRECTIONAL_LIGHTS && !legacyProfile())
    for (int i = 0, count = frameData.lightCounts[opaque(0)]; i < count; ++i) {
      vec3 radiance = directionalLight(frameData.directionalLights[summationIndex(i, count)], N, mask, textures, L);
      addLight(sums, surface, radiance, L);
    }
  if (objectListInUse()) {
    // srp: min(count, 8) per pixel; legacy: list positions 0-3 per pixel.
    int perPixel = legacyProfile() ? kLegacyPixelLights : kMaxLightsPerObject;
    int count = min(objectListCount(), perPixel);
    // Mutant: srp's loop runs to count (objectLightIndex wraps past 8).
    if (MUTANT == MUTANT_UNSANITISED_OBJECT_LOOP && !legacyProfile()) count = objectListCount();
    for (int k = 0; k < count; ++k) {
      vec3 radiance = packedLight(frameData.otherLights[objectLightIndex(summationIndex(k, count))], p, N, mask, textures, L);
      addLight(sums, surface, radiance, L);
    }
  } else if (clusteredLights()) {
    ivec2 range = clusterRange(clusterOf(vClip, p));
    for (int k = 0; k < range.y; ++k) {
      vec3 radiance = packedLight(frameData.otherLights[clusterLight(range.x + summationIndex(k, range.y))], p, N, mask, textures, L);
      addLight(sums, surface, radiance, L);
    }
  } else {
    for (int i = 0, count = frameData.lightCounts[opaque(1)]; i < count; ++i) {
      vec3 radiance = packedLight(frameData.otherLights[summationIndex(i, count)], p, N, mask, textures, L);
      addLight(sums, surface, radiance, L);
    }
  }
  // Vertex lights: the legacy profile, which is Lambert only (SPEC 2).
  if (legacyProfile()) sums.radiance = flushed(sums.radiance + vVertexLighting);
  outColor = vec4(brdfColour(surface, sums), 1.0);
}
