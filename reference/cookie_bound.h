// SPEC 3.10's cookie at one point with the bound on what a float32 lookup
// may return instead (docs/tolerances.md "Cookies"): SPEC 7's filtering term
// (the weight precision, 2^-4 unless the device reports more, of the taps'
// spread per axis), the coordinate's float error times the
// cookie's local gradient, and the blend's roundings. The coordinate error is
// taken as a position error and the lookup redone at the six points that far
// away along the axes: the largest change is the gradient times the error,
// also where the ball crosses a texel row, the spot's clamp or a cube face
// boundary, so at cube edges and corners the value of either face is
// admissible (as VK-GL-CTS's cube lookup verifier allows).
#pragma once

#include "lighting/scene.h"
#include "reference/tolerance_model.h"

namespace reference {

struct CookieBound {
  double value = 1;
  double errorBound = 0;
};

// `positionError`: how far the float32 position the GPU looks the cookie up
// at may be from p (world units), already including the light's own.
// `weightPrecision`: how far each filter weight may be off (SPEC 7).
CookieBound cookieWithBound(const lighting::Light& light, const lighting::Vec3& p, double positionError,
                            double weightPrecision = tolerance::kFilterWeightPrecision);

}  // namespace reference
