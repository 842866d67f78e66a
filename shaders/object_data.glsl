// The per-object uniform block of the forward and G-buffer passes, std140 as
// lighting::GpuObjectBlock lays it out. Apart from light_data.glsl so that
// the deferred light and composite passes, which draw no object, do not
// declare it (their pipelines have no ObjectBlock binding).
#ifndef LIGHTCTS_OBJECT_DATA_GLSL
#define LIGHTCTS_OBJECT_DATA_GLSL

#include "shader_interface.glsl"
#include "light_data.glsl"

layout(std140, LIGHTCTS_BINDING(ObjectBlock)) uniform ObjectBlock {
  mat4 model;           // local to camera-relative world
  mat4 normalMatrix;    // the rotation R (SPEC 1)
  vec4 albedo;
  ivec4 lightList;      // x: list count (may exceed 8), y: lightmap, z: shadow mask, w: 1 when the list is in use
  ivec4 lightIndices[2];  // packed indices into otherLights, -1 past the end
  vec4 lightmapTransform;
  vec4 material;        // x: metallic, y: smoothness, z: 1 for the srp BRDF (SPEC 3.8), 0 Lambert
  ivec4 raster;         // x: 1 when every vertex lies in front of the camera (the snapping variants snap only such objects)
} objectData;

// The full shader asks the object whether its list is in use.
bool objectListInUse() { return PER_OBJECT_LISTS && objectData.lightList[opaque(3)] != 0; }

// The object's list count (it may exceed 8), and its material with the
// srp flag (z) that decides the BRDF: both steer the shaders, so read at
// opaque indices (light_data.glsl).
int objectListCount() { return objectData.lightList[opaque(0)]; }
vec4 objectMaterial() {
  return vec4(objectData.material.xy, objectData.material[opaque(2)], objectData.material.w);
}

// The list index k of this object (0 <= k < 8).
int objectLightIndex(int k) {
  // Mutant: a loop that runs past 8 wraps around and applies lights again.
  if (MUTANT == MUTANT_UNSANITISED_OBJECT_LOOP) k = k % 8;
  return objectData.lightIndices[k / 4][k % 4];
}

#endif
