// SPEC 3.1-3.3 evaluated in double at one point, with a first-order bound on
// the error a float32 evaluation of the same formulas may make (the arithmetic
// part of the tolerance model, docs/tolerances.md).
#pragma once

#include "lighting/light_math.h"
#include "lighting/scene.h"

#include <vector>

namespace reference {

using lighting::Vec3;

struct LightSum {
  Vec3 value{0.0};   // sum of finalColor * saturate(dot(N, L)) * attenuation, without albedo
  Vec3 errorBound{0.0};
  int evaluations = 0;
};

// Where the point's float32 position comes from, for the position error.
struct PositionContext {
  Vec3 camera{0.0};
  double objectExtent = 0;  // |object centre - camera| + object radius
};

class LightEvaluator {
 public:
  // `weights`: a factor on each scene light's finalColor (the fade weights of
  // lighting/light_fade.h, LightSelection::weightsBySceneLight); empty: all 1,
  // as for `--ideal`. The factor is exact in the model (the packed data holds
  // float(finalColor * weight)), so the error bound scales with it.
  LightEvaluator(const lighting::Scene& scene, lighting::Profile profile, const std::vector<double>& weights = {});

  // Adds the contributions of `lights` (scene indices) at p with unit normal N.
  void accumulate(const std::vector<int>& lights, const Vec3& p, const Vec3& N,
                  const PositionContext& where, LightSum& sum) const;

 private:
  struct Prepared {
    bool directional = false;
    Vec3 finalColor{0.0};  // times the light's weight
    Vec3 position{0.0};
    Vec3 towardLight{0.0};  // directional: L = -direction
    Vec3 spotDirection{0.0};
    double invRangeSq = 0;
    lighting::SpotFactors spot;
    double shadowMask = 1;  // SPEC 3.5; 1 until lightmaps exist
  };
  std::vector<Prepared> lights_;
};

}  // namespace reference
