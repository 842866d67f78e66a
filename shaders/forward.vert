#version 450
#extension GL_GOOGLE_include_directive : require
// Forward vertex stage: camera-relative position and rotated normal for the
// fragment stage, and the legacy profile's vertex lights (SPEC 4: list
// positions 4-7, evaluated here with the rotated, normalised vertex normal
// and interpolated perspective-correct).
#include "lighting.glsl"
#include "object_data.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;

// Varyings have the same names in both stages: GLSL 330 (the OpenGL backend,
// via SPIRV-Cross) links stages by name, not by location.
layout(location = 0) out vec3 vPosition;  // camera-relative world position (absolute in the absolute-coordinates mutant)
layout(location = 1) out vec3 vNormal;
layout(location = 2) out vec3 vVertexLighting;
layout(location = 3) out vec2 vLightmapUv;  // SPEC 3.6: u = x_local / sx + 0.5, v = z_local / sz + 0.5
layout(location = 4) out vec4 vClip;  // gl_Position, for the clustered mode's tile (clusters.glsl)

const int kLegacyPixelLights = 4;
const int kMaxLightsPerObject = 8;

void main() {
  vec4 position = objectData.model * vec4(inPosition, 1.0);
  vec3 N = unitVector(mat3(objectData.normalMatrix) * inNormal);
  // Camera-relative; absolute in the absolute-coordinates mutant.
  vec3 worldPosition = mutantWorldPosition(position.xyz);
  vPosition = worldPosition;
  vNormal = N;
  vVertexLighting = vec3(0.0);
  // Affine in the local position, so interpolating it is exact.
  vLightmapUv = inPosition.xz * objectData.lightmapTransform.xy + objectData.lightmapTransform.zw;
  if (legacyProfile()) {
    int count = min(objectListCount(), kMaxLightsPerObject);
    if (MUTANT == MUTANT_UNSANITISED_OBJECT_LOOP) count = objectListCount();
    if (MUTANT == MUTANT_LEGACY_VERTEX_LIGHTS_DROPPED) count = 0;
    // Mutant: rotation * scale * normal, never normalised.
    vec3 vertexNormal = MUTANT == MUTANT_VERTEX_NORMAL_NOT_NORMALISED ? mat3(objectData.model) * inNormal : N;
    vec3 L;  // unused: vertex lights are Lambert (the legacy profile has no srp BRDF)
    LightTextures textures = lightTexturesAtVertex(worldPosition);  // SPEC 3.10 at the vertex; no shadow map
    for (int k = kLegacyPixelLights; k < count; ++k) {
      int listed = kLegacyPixelLights + summationIndex(k - kLegacyPixelLights, count - kLegacyPixelLights);
      vVertexLighting = flushed(vVertexLighting + packedLight(frameData.otherLights[objectLightIndex(listed)],
                                                              worldPosition, vertexNormal, vec4(1.0), textures, L));
    }
  }
  // The snapping variants move the vertex on the device's sub-pixel grid (admissible.glsl).
  gl_Position = snappedClipPosition(frameData.viewProjection * position, frameData.rasterGrid, objectData.raster.x != 0);
  vClip = gl_Position;
}
