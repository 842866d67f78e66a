#include "shaders/shader_constants.h"

#include "lighting/cookie_slots.h"
#include "lighting/shadow_slots.h"

namespace shaders {

ConstantValues constantValues(const lighting::ShaderFeatures& f, const ShaderVariant& variant) {
  ConstantValues v{};
  const bool all = !variant.specialised;
  v[kDirectionalLights] = all || f.directionalLights;
  v[kPointLights] = all || f.pointLights;
  v[kSpotLights] = all || f.spotLights;
  // The full shader can afford these on for any scene: it checks the
  // object's and frame's flags at run time (light_data.glsl).
  v[kPerObjectLists] = all || f.perObjectLists;
  v[kVertexLights] = all || f.vertexLights;
  v[kShadowMask] = all || f.shadowMask;
  v[kAmbient] = all || f.ambient;
  v[kLightmap] = all || f.lightmap;
  // The full shader reads the buffer format from DeferredFrameBlock.
  v[kLdr8Buffer] = all || f.ldr8Buffer;
  // The full shader asks each object's material (object_data.glsl).
  v[kSpecularBrdf] = all || f.specularBrdf;
  // The full shader asks each light's cookie slot (cookies.glsl).
  v[kCookies] = all || f.cookies;
  v[kShadowMaps] = all || f.shadowMaps;
  // The full shader asks FrameBlock.lightCounts.w (clusters.glsl).
  v[kClusteredLights] = all || f.clusteredLights;
  v[kMutant] = static_cast<std::int32_t>(variant.mutant);
  v[kAdmissible] = static_cast<std::int32_t>(variant.admissible);
  v[kOpaqueUniformReads] = variant.opaqueUniformReads;
  // The full shader looks up every slot; the specialised one those in use.
  v[kCookieTextures] = all ? lighting::kMaxCookieTextures : f.cookieTextures;
  v[kCookieCubes] = all ? lighting::kMaxCookieCubes : f.cookieCubes;
  v[kShadowMapTextures] = all ? lighting::kMaxShadowMaps : f.shadowMapTextures;
  v[kShadowMapCubes] = all ? lighting::kMaxShadowCubes : f.shadowMapCubes;
  v[kShadowTent] = all || f.shadowTent;
  v[kLightCookieSlot] = kEverySlotInUse;
  v[kLightShadowSlot] = kEverySlotInUse;
  return v;
}

ShaderBuild shaderBuildOf(const ConstantValues& constants) {
  return constants[kAdmissible] != 0 ? ShaderBuild::AdmissibleVariants : ShaderBuild::Model;
}

ConstantValues lightPassConstants(ConstantValues v, const lighting::LightPassSlots& slots,
                                  const ShaderVariant& variant) {
  if (!variant.specialised) return v;
  v[kLightCookieSlot] = slots.cookie >= 0 ? slots.cookie : kNoSlot;
  v[kLightShadowSlot] = slots.shadow >= 0 ? slots.shadow : kNoSlot;
  return v;
}

}  // namespace shaders
