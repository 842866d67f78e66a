// The object's baked maps (SPEC 3.5, 3.6) and what the forward pass and the
// G-buffer pass read from them, written once so that deferred's base and
// mask are the forward pass's operation for operation. Float textures with
// LINEAR filtering and clamp to edge; objects without maps get a 1x1 texture
// and flags of 0. The OpenGL backend binds them by name (GLSL 330 has no
// binding qualifiers). Needs lighting.glsl and object_data.glsl first.
#ifndef LIGHTCTS_OBJECT_MAPS_GLSL
#define LIGHTCTS_OBJECT_MAPS_GLSL

layout(LIGHTCTS_BINDING(lightmapTexture)) uniform sampler2D lightmapTexture;
layout(LIGHTCTS_BINDING(shadowMaskTexture)) uniform sampler2D shadowMaskTexture;

// SPEC 3.5: the object's shadow mask at the fragment, all ones without one.
vec4 objectShadowMask(vec2 lightmapUv) {
  if (SHADOW_MASK && objectData.lightList[opaque(2)] != 0)
    return filteredTexel(shadowMaskTexture, lightmapUv, false, frameData.filterGrid.x);
  return vec4(1.0);
}

// The radiance sum before any light: what the diffuse colour multiplies
// besides the lights, ambient and the baked light (SPEC 3.6, the lightmap's
// irradiance).
LightSums unlitSums(vec2 lightmapUv) {
  LightSums sums = LightSums(vec3(0.0), vec3(0.0));
  if (AMBIENT) sums.radiance += frameData.ambient.rgb;
  if (LIGHTMAP && objectData.lightList[opaque(1)] != 0)
    sums.radiance += filteredTexel(lightmapTexture, lightmapUv, false, frameData.filterGrid.x).rgb;
  return sums;
}

#endif
