// The idealised reference of a scene with `"expect": {"against": "realtime"}`
// (docs/scene-format.md, docs/model.md): on a lightmapped object, every baked
// light (mode baked, or a mixed light demoted by SPEC 5.3) is evaluated in
// real time at the pixel instead of read from the lightmap: SPEC 3.2's
// formula (inverse-squared with the range window, spot factor) times the
// visibility of SPEC 3.6's shadow ray from p + 1e-3 N.
//
// Its allowance says how far a *correct* inverse-squared bake, sampled by a
// float32 LINEAR filter, may be from that: the bake holds the same irradiance
// at the texel centres, so the difference is the bilinear interpolation
// between them plus the filtering term (docs/tolerances.md section 5).
#pragma once

#include "lighting/frame.h"
#include "reference/bvh.h"
#include "reference/lightmap_sampling.h"

#include <vector>

namespace reference {

class RealtimeBakedLights {
 public:
  // Evaluates the irradiance at every texel centre of every lightmapped
  // object once (camera independent), on `threads` threads (0: all).
  RealtimeBakedLights(const lighting::PreparedScene& prepared, const Bvh& bvh, int threads = 0);

  // E_rt: the real-time irradiance of every baked light at p with unit normal N.
  Vec3 irradiance(const Vec3& p, const Vec3& N) const;

  struct Sample {
    Vec3 value{0.0};      // E_rt(p)
    Vec3 allowance{0.0};  // |bilerp(E_rt at the four texel centres)(uv) - E_rt(p)| + filtering + texel rounding
    Vec3 interpolation{0.0};  // the first part alone (tests, docs)
  };
  // On lightmapped `object` at p (normal N) whose lightmap UV is `uv`.
  Sample sample(int object, const Vec3& p, const Vec3& N, const Vec2& uv) const;

  // E_rt at the centre of texel (i, j) of `object`'s map, with the plane's normal.
  const Vec3& texelIrradiance(int object, int i, int j) const;

  const std::vector<int>& bakedLights() const { return bakedLights_; }

 private:
  const lighting::PreparedScene& prepared_;
  const Bvh& bvh_;
  std::vector<int> bakedLights_;                  // scene light indices
  std::vector<std::vector<Vec3>> texelIrradiance_;  // per object: N * N, texel (i, j) at j * N + i
};

}  // namespace reference
