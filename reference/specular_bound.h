// SPEC 3.8's specular lobe at one point, with the bound on how far a float32
// evaluation of it may land (docs/tolerances.md "Specular lobe"). The lobe is
// the model's most ill-conditioned term: near the peak, d = nh2 (r2 - 1) +
// 1.00001 is a difference of two numbers near 1 that ends near r2 + 1e-5, so
// an absolute error in nh2 becomes a relative error 1/d larger in d, twice
// that in d2. The bound is carried as an interval through every step: the
// clamps (saturate, max(0.1, lh2)) and the square are monotone, so an
// interval maps onto the exact interval of its image, and both sides of a
// clamp stay admissible within the input's error; where L + V is shorter than
// its own error, SafeNormalize's H may be any unit vector (or 0), and the
// interval of nh and lh widens to all of [0, 1].
#pragma once

#include "lighting/scene.h"

namespace reference {

using lighting::Vec3;

// The float32 error of a unit vector v, split into its length error (along
// v) and its direction error (across v): a dot product with a unit vector w
// at angle t to v moves by |v.w| times the first and only sin(t) times the
// second, so at the peak (N = H) the direction errors drop out to first
// order; that is what keeps the bound from being far looser than the
// arithmetic there (tolerance_model.h derives each constant).
struct VectorError {
  double length = 0;
  double direction = 0;
};

struct LobeInputErrors {
  VectorError normal;  // N: interpolated, then normalised
  VectorError view;    // V
  VectorError light;   // L
};

struct SpecularBound {
  double value = 0;       // specularStrength in double
  double errorBound = 0;  // largest |float32 specularStrength - value|
  bool halfVectorAmbiguous = false;  // |L + V| within its error: H undetermined
};

// `smoothness` is the scene's value: the float32 roughness is square(1 -
// float(smoothness)), and its rounding is part of the bound.
SpecularBound specularWithBound(const Vec3& N, const Vec3& V, const Vec3& L, double smoothness,
                                const LobeInputErrors& errors);

}  // namespace reference
