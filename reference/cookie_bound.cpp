#include "reference/cookie_bound.h"

#include "lighting/cookie.h"
#include "reference/tolerance_model.h"

#include <algorithm>
#include <cmath>

namespace reference {

using namespace lighting;
namespace tol = tolerance;

CookieBound cookieWithBound(const Light& light, const Vec3& p, double positionError, double weightPrecision) {
  CookieBound out;
  if (!light.cookie) return out;
  const CookieCoordinates at = cookieCoordinates(light, p);
  double spread = 0, magnitude = 0;
  out.value = 0;  // SPEC 3.10: 0 behind a spot's apex
  if (!at.outside) {
    const std::array<CookieTap, 4> taps = cookieTaps(light, at);
    out.value = blendTaps(*light.cookie, taps);
    double lo = 1e300, hi = -1e300;
    for (const CookieTap& tap : taps) {
      const double v = tapValue(*light.cookie, tap);
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
    spread = hi - lo;
    magnitude = std::max(std::abs(lo), std::abs(hi));
  }
  // The weights' precision and the blend's roundings (as for the lightmaps).
  const double fromWeights = tol::kFilterWeightErrorsPerSample * weightPrecision * spread;
  const double fromBlend = tol::kFilterBlendRoundingSteps * tol::kStepRoundoff * magnitude;
  // The coordinate's error: the lookup redone positionError away.
  double fromCoordinate = 0;
  for (int axis = 0; axis < 3; ++axis)
    for (double sign : {-1.0, 1.0}) {
      Vec3 q = p;
      q[axis] += sign * positionError;
      fromCoordinate = std::max(fromCoordinate, std::abs(cookieValue(light, q) - out.value));
    }
  out.errorBound = fromWeights + fromBlend + fromCoordinate;
  return out;
}

}  // namespace reference
