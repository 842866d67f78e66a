// How the reference reads an object's baked maps (SPEC 3.5, 3.6): the hit's
// lightmap UV, the four texels a LINEAR filter blends there, and the bound on
// what a float32 filter may return instead of the exact bilinear value
// (SPEC 7's texture-filtering term, docs/tolerances.md section 4).
#pragma once

#include "lighting/baked_lighting.h"
#include "lighting/transform.h"
#include "reference/tolerance_model.h"

namespace reference {

using lighting::Vec2;
using lighting::Vec3;
using lighting::Vec4;

// SPEC 3.6's plane UV of a world point: back to local space through the
// inverse of the object transform (double), then u = x/sx + 0.5, v = z/sz + 0.5.
Vec2 lightmapUvOfWorldPoint(const lighting::MeshSpec& plane, const lighting::ObjectTransform& transform,
                            const Vec3& world);

// The four texels a bilinear sample at `uv` blends (clamped to the edge) and
// its weights, by the same rule as lighting::sampleBilinear: t00 = (i0, j0),
// t10 = (i1, j0), t01 = (i0, j1), t11 = (i1, j1); value =
// (t00 (1 - fx) + t10 fx) (1 - fy) + (t01 (1 - fx) + t11 fx) fy.
struct TexelFootprint {
  int i0 = 0, i1 = 0, j0 = 0, j1 = 0;
  double fx = 0, fy = 0;
};
TexelFootprint texelFootprint(int resolution, const Vec2& uv);

// The largest |float32 filter - exact bilinear value| of one channel, for a
// sample whose four texels have spread `spread` (max - min) and magnitudes at
// most `magnitude`, in an N x N map:
//   2 x w x spread                    weight precision w (2^-4 unless the device reports more), one error per axis
//   + 2 x N x 16u x spread            the float UV's error, at a slope <= N x spread per axis
//   + 6u x magnitude                  the blend's own roundings
double filteringErrorBound(double spread, double magnitude, int resolution,
                           double weightPrecision = tolerance::kFilterWeightPrecision);

// The same per channel of a lighting::sampleBilinear result.
Vec4 filteringErrorBound(const lighting::BilinearSample& sample, int resolution,
                         double weightPrecision = tolerance::kFilterWeightPrecision);

}  // namespace reference
