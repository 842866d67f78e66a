// The scalar formulas of SPEC sections 1 and 3, in double precision. Light
// selection (importance), the reference renderer and the baker all call these;
// the GPU copy of the same formulas is shaders/lighting.glsl.
#pragma once

#include "lighting/scene.h"

namespace lighting {

constexpr double kMinDistanceSquared = 1e-5;   // SPEC 3.2: distSqr = max(dot(ray, ray), 1e-5)
constexpr double kMinRangeSquared = 1e-5;      // SPEC 3.2: invRangeSq = 1 / max(range^2, 1e-5)
constexpr double kMinSpotCosineSpan = 0.001;   // SPEC 3.3: a = 1 / max(cosInner - cosOuter, 0.001)
constexpr double kLegacyInnerTangentRatio = 46.0 / 64.0;  // SPEC 3.4

inline double saturate(double x) { return x < 0 ? 0 : (x > 1 ? 1 : x); }
inline double square(double x) { return x * x; }
double luminance(const Vec3& c);  // SPEC 1

// SPEC 3.2: invRangeSq = 1 / max(range^2, 1e-5).
double inverseRangeSquared(double range);

// SPEC 3.2: rangeAtt = square(saturate(1 - square(distSqr * invRangeSq))).
double rangeAttenuation(double distanceSquared, double invRangeSquared);

// SPEC 3.3: the spot factor is square(saturate(dot(spotDir, L) * a + b)).
struct SpotFactors {
  double a = 0;  // point lights: a = 0, b = 1
  double b = 1;
};
SpotFactors spotFactors(double outerAngleDeg, double innerAngleDeg);
double spotAttenuation(double cosAngle, const SpotFactors& f);

// SPEC 3.4: the inner half-angle (degrees) from tan(ri) = 46/64 tan(ro); 90 at ro = 90.
double legacyInnerHalfAngleDeg(double outerHalfAngleDeg);

// The full inner cone angle a light uses under a profile (SPEC 4): the scene's
// value in `srp` when present, else the legacy rule.
double effectiveInnerSpotAngleDeg(const Light& light, Profile profile);

// a and b for a light under a profile; point and directional lights get (0, 1).
SpotFactors lightSpotFactors(const Light& light, Profile profile);

}  // namespace lighting
