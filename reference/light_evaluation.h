// SPEC 3.1-3.3 evaluated in double at one point, with a first-order bound on
// the error a float32 evaluation of the same formulas may make (the arithmetic
// part of the tolerance model, docs/tolerances.md).
#pragma once

#include "lighting/baked_lighting.h"
#include "lighting/light_math.h"
#include "lighting/scene.h"
#include "reference/shadow_maps.h"
#include "reference/specular_bound.h"
#include "reference/surface_inputs.h"
#include "reference/tolerance_model.h"

#include <vector>

namespace reference {

using lighting::Vec3;

struct LightSum {
  Vec3 value{0.0};   // sum of finalColor * saturate(dot(N, L)) * attenuation (the radiance), without albedo
  Vec3 errorBound{0.0};
  // srp (SPEC 3.8): the sum of radiance * specularStrength, which F0
  // multiplies (the diffuse colour multiplies `value`), and its bound.
  Vec3 specular{0.0};
  Vec3 specularBound{0.0};
  int evaluations = 0;
  // Per channel, how many terms were > 0: the deferred light buffers round
  // once or twice per light that adds something (deferred_buffers.h).
  lighting::Vec3 contributing{0.0};
  // SPEC 3.9: some light with a real-time shadow added light here (its
  // unshadowed term > 0), and the widest of those lights' intervals
  // [s_lo, s_hi] (the ambiguity the scene's cap counts).
  bool shadowed = false;
  double widestShadowSpan = 0;
  double widestShadowLo = 1, widestShadowHi = 1;  // that light's [s_lo, s_hi]
  // Per channel, without albedo: how far the shadowed lights' terms may
  // change over the snapping square where a shadow edge crosses it
  // (docs/tolerances.md section 2), beyond what its sampled points show.
  Vec3 shadowEdgeChange{0.0};
};

// SPEC 3.9's real-time shadows of a frame, for the evaluator: per scene
// light its reference map (null without one), or with `idealVisibility` the
// ray-traced visibility of `--ideal` instead of every map.
struct RealtimeShadows {
  std::vector<const ReferenceShadowMap*> mapOfLight;
  const Bvh* idealVisibility = nullptr;
  double shadowDistance = 0;  // pipeline.shadow_distance
};

// Where the shaded point sits for SPEC 3.9's fade: its view depth and how far
// a float32 view depth may be from it.
struct ShadowReceiver {
  double viewDepth = 0;
  double viewDepthError = 0;
};

// Where the point's float32 position comes from, for the position error.
struct PositionContext {
  Vec3 camera{0.0};
  double objectExtent = 0;  // |object centre - camera| + object radius
  // Deferred path: the light pass reconstructs the position from depth, off
  // by up to this much (world units; deferred_buffers.h), instead of
  // interpolating it.
  double reconstructionError = 0;
  // How far vertex snapping may move the surface point the pixel centre sees
  // (world units, along the surface; tolerance_model.h): the factors that
  // multiply an arithmetic error are taken at their highest over it too.
  double snapMove = 0;
  // The fragment's position and normal inputs' errors (reference/surface_inputs.h);
  // null: a vertex of the camera-relative magnitude |p - camera| + objectExtent.
  const SurfaceErrors* inputs = nullptr;
  // The value alone, no bound: a point the sub-pixel term shades only for
  // its value (reference_renderer.cpp).
  bool valueOnly = false;
};

// The shadow mask at a point (SPEC 3.5): the object's mask sampled at the
// fragment's lightmap UV, and per channel the bound on how far a float32
// filter's sample may be from it (lightmap_sampling.h). No mask: all ones.
struct ShadowMaskAtPoint {
  lighting::Vec4 value{1.0};
  lighting::Vec4 error{0.0};
};

// An srp material's specular lobe at the point (SPEC 3.8): the view vector
// and its float32 error, and the smoothness (roughness = square(1 - s)).
struct LobeAtPoint {
  Vec3 view{0.0};
  VectorError viewError;
  VectorError normalError;
  double smoothness = 0.5;
};

struct ShadowFactor;  // light_evaluation.cpp: one light's shadowAtten and its interval

class LightEvaluator {
 public:
  // `weights`: a factor on each scene light's finalColor (the fade weights of
  // lighting/light_fade.h, LightSelection::weightsBySceneLight); empty: all 1,
  // as for `--ideal`. The factor is exact in the model (the packed data holds
  // float(finalColor * weight)), so the error bound scales with it.
  // `shadowMaskChannels`: per scene light, its shadow-mask channel or -1
  // (ShadowMaskAssignment::channelOfLight); empty: no light has one.
  // `filterWeightPrecision`: SPEC 7's filter weight precision, for cookies.
  LightEvaluator(const lighting::Scene& scene, lighting::Profile profile, const std::vector<double>& weights = {},
                 const std::vector<int>& shadowMaskChannels = {},
                 double filterWeightPrecision = tolerance::kFilterWeightPrecision,
                 const RealtimeShadows* shadows = nullptr);

  // Adds the contributions of `lights` (scene indices) at p with unit normal N.
  // `mask`: the object's shadow mask at p, or null where there is none (an
  // object without maps, and legacy vertex lights, which the GPU evaluates
  // with a mask of 1): SPEC 3.5's shadowMask is then 1.
  // `lobe`: an srp material's lobe (adds LightSum::specular), or null (Lambert).
  // `receiver`: where p sits for SPEC 3.9's real-time shadows, or null where
  // they do not apply (legacy vertex lights: the vertex stage reads no map).
  void accumulate(const std::vector<int>& lights, const Vec3& p, const Vec3& N,
                  const PositionContext& where, LightSum& sum, const ShadowMaskAtPoint* mask = nullptr,
                  const LobeAtPoint* lobe = nullptr, const ShadowReceiver* receiver = nullptr) const;

 private:
  struct Prepared {
    bool directional = false;
    Vec3 finalColor{0.0};  // times the light's weight
    Vec3 position{0.0};
    Vec3 towardLight{0.0};  // directional: L = -direction
    Vec3 spotDirection{0.0};
    double invRangeSq = 0;
    lighting::SpotFactors spot;
    int shadowMaskChannel = -1;  // SPEC 3.5: c, or -1 (no channel, or strength 0)
    double shadowStrength = 0;
    const lighting::Light* cookieLight = nullptr;  // SPEC 3.10: the light, when it has a cookie
    // SPEC 3.9: the light's real-time shadow, its map or (--ideal) the light
    // itself for ray-traced visibility; both null without one.
    const ReferenceShadowMap* shadowMap = nullptr;
    const lighting::Light* idealShadowLight = nullptr;
    double realtimeShadowStrength = 0;
  };
  ShadowFactor shadowAt(const Prepared& light, const Vec3& p, const Vec3& N, const LookupError& error,
                        const ShadowReceiver& receiver) const;
  std::vector<Prepared> lights_;
  double filterWeightPrecision_;
  const Bvh* idealVisibility_ = nullptr;
  double shadowDistance_ = 0;
};

}  // namespace reference
