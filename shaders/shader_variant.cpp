#include "shaders/shader_variant.h"

namespace shaders {

const std::vector<MutantName>& mutantNames() {
  static const std::vector<MutantName> names = {
      {Mutant::DistanceClamp1em4, "distance-clamp-1e-4", "distSqr clamped at 1e-4 instead of 1e-5 (SPEC 3.2)"},
      {Mutant::UnsquaredRange, "unsquared-range", "rangeAtt without the outer square (SPEC 3.2)"},
      {Mutant::UnsquaredSpot, "unsquared-spot", "spotAtt without the square (SPEC 3.2)"},
      {Mutant::FullSpotAngle, "full-spot-angle",
       "the cone uses the full spot angle where SPEC 3.3 takes the half angle"},
      {Mutant::UnsanitisedObjectLoop, "unsanitised-object-loop",
       "the per-object loop runs to count instead of min(count, 8), wrapping past 8 (SPEC 5.2)"},
      {Mutant::HalfPrecisionAttenuation, "half-precision-attenuation",
       "the attenuation of point and spot lights rounded through a 16-bit float"},
      {Mutant::AbsoluteCoordinates, "absolute-coordinates",
       "positions in absolute world coordinates in float32, not camera-relative (SPEC 7, far from the origin)"},
      {Mutant::VertexNormalNotNormalised, "vertex-normal-not-normalised",
       "legacy vertex lights use the rotated and scaled normal without normalising it (SPEC 4)"},
      {Mutant::DirectionalNotSaturated, "directional-not-saturated",
       "directional lights use dot(N, L) without clamping it at 0 (SPEC 3.1)"},
      {Mutant::SpotDirectionFlipped, "spot-direction-flipped",
       "the spot cone tests against the light's travel direction instead of spotDir = -direction (SPEC 3.2)"},
      {Mutant::LocalNotSaturated, "local-not-saturated",
       "point and spot lights use dot(N, L) without clamping it at 0 (SPEC 3.2)"},
      {Mutant::LegacyVertexLightsDropped, "legacy-vertex-lights-dropped",
       "the legacy profile lights only list positions 0-3, never the vertex lights 4-7 (SPEC 4)"},
      {Mutant::ShadowMaskChannelOffByOne, "shadow-mask-channel-off-by-one",
       "a mixed light reads shadow-mask channel (c + 1) mod 4 instead of its own channel c (SPEC 3.5)"},
      {Mutant::ShadowStrengthIgnored, "shadow-strength-ignored",
       "the shadow mask applies in full, mask[c] instead of lerp(1, mask[c], strength) (SPEC 3.5)"},
      {Mutant::DemotedLightStillLit, "demoted-light-still-lit",
       "a mixed light demoted in SPEC 5.3 is lit in real time as well as baked"},
      {Mutant::LegacyFalloffBaked, "legacy-falloff-baked",
       "lights with bake_falloff inverse_squared are baked with the legacy falloff (SPEC 3.6)"},
      {Mutant::UnclampedLdrDecode, "unclamped-ldr-decode",
       "the ldr8 light buffer decodes -log2(x) without max(x, 1/255), so a dark texel decodes to infinity (SPEC 3.7)"},
      {Mutant::PointVolumeOutsideOnly, "point-volume-outside-only",
       "sphere light volumes drawn front faces with depth test LESS_OR_EQUAL: nothing lit with the camera inside (SPEC 3.7)"},
      {Mutant::D2WithoutEpsilon, "d2-without-epsilon",
       "d2 = square(nh2 (r2 - 1) + 1) without the 1.00001: infinite at the peak of smoothness 1, too bright near it (SPEC 3.8)"},
      {Mutant::Lh2NotClamped, "lh2-not-clamped",
       "specularStrength divides by lh2 instead of max(0.1, lh2): too bright at grazing light and view (SPEC 3.8)"},
      {Mutant::F0AlbedoAlways, "f0-albedo-always",
       "F0 = albedo whatever the metallic, instead of lerp(0.04, albedo, metallic) (SPEC 3.8)"},
      {Mutant::ViewAbsoluteCoordinates, "view-absolute-coordinates",
       "V = normalize(camera - p) computed from absolute float32 coordinates, not camera-relative (SPEC 3.8, far from the origin)"},
      {Mutant::HalfVectorNotNormalised, "half-vector-not-normalised",
       "H = L + V without SafeNormalize: the lobe saturates over a wide plateau (SPEC 3.8)"},
      {Mutant::DirectionalCookieClamped, "directional-cookie-clamped",
       "the directional cookie is clamped to edge instead of tiled: one tile, then its border texels (SPEC 3.10)"},
      {Mutant::CubeCookieRotated, "cube-cookie-rotated-90",
       "the point cookie's cube is sampled at the direction turned 90 degrees about y (SPEC 3.10)"},
      {Mutant::CookieVFlipped, "cookie-v-flipped",
       "2D cookies are sampled at 1 - v: image row 0 taken as v = 1 (SPEC 3.10)"},
      {Mutant::ShadowCompareLess, "shadow-compare-less",
       "the shadow-map compare is LESS instead of LESS_OR_EQUAL: equal depths shadow (SPEC 3.9)"},
      {Mutant::ShadowDepthBiasIgnored, "shadow-depth-bias-ignored",
       "the shadow lookup's receiver leaves out depth_bias * L (SPEC 3.9)"},
      {Mutant::ShadowNormalBiasAlongL, "shadow-normal-bias-along-l",
       "the normal bias moves the receiver along L instead of N (SPEC 3.9)"},
      {Mutant::ShadowTexelCentresShifted, "shadow-texel-centres-shifted",
       "2D shadow-map lookups half a texel off the texel centres (SPEC 3.9)"},
      {Mutant::ShadowFadeIgnored, "shadow-fade-ignored",
       "shadows never fade toward shadow_distance (SPEC 3.9)"},
      {Mutant::CubeShadowWrongAxis, "cube-shadow-wrong-axis",
       "the point light's cube face is chosen with x and z exchanged (SPEC 3.9)"},
      {Mutant::ShadowStrengthAsPower, "shadow-strength-as-power",
       "shadowAtten = saturate(pow(s, strength) + fade) instead of lerp(1, s, strength) (SPEC 3.9)"},
  };
  return names;
}

std::optional<Mutant> mutantFromName(std::string_view name) {
  if (name == "none") return Mutant::None;
  for (const MutantName& m : mutantNames())
    if (m.name == name) return m.mutant;
  return std::nullopt;
}

std::string_view mutantName(Mutant mutant) {
  for (const MutantName& m : mutantNames())
    if (m.mutant == mutant) return m.name;
  return "none";
}

lighting::DepthCompare shadowLookupCompare(Mutant mutant) {
  return mutant == Mutant::ShadowCompareLess ? lighting::DepthCompare::Less : lighting::kShadowLookupCompare;
}

lighting::VolumeRule volumeRule(Mutant mutant) {
  return mutant == Mutant::PointVolumeOutsideOnly ? lighting::VolumeRule::OutsideOnlyMutant
                                                  : lighting::VolumeRule::Model;
}

}  // namespace shaders
