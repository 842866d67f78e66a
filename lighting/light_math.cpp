#include "lighting/light_math.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lighting {
namespace {
double radians(double deg) { return deg * std::numbers::pi / 180.0; }
double degrees(double rad) { return rad * 180.0 / std::numbers::pi; }
}  // namespace

double luminance(const Vec3& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

double inverseRangeSquared(double range) {
  return 1.0 / std::max(range * range, kMinRangeSquared);
}

double rangeAttenuation(double distanceSquared, double invRangeSquared) {
  return square(saturate(1.0 - square(distanceSquared * invRangeSquared)));
}

SpotFactors spotFactors(double outerAngleDeg, double innerAngleDeg) {
  const double cosOuter = std::cos(radians(outerAngleDeg / 2));
  const double cosInner = std::cos(radians(innerAngleDeg / 2));
  SpotFactors f;
  f.a = 1.0 / std::max(cosInner - cosOuter, kMinSpotCosineSpan);
  f.b = -cosOuter * f.a;
  return f;
}

double spotAttenuation(double cosAngle, const SpotFactors& f) {
  return square(saturate(cosAngle * f.a + f.b));
}

double legacyInnerHalfAngleDeg(double outerHalfAngleDeg) {
  // The outer half-angle is at most 90 degrees (spot_angle_deg <= 180). tan(90)
  // is infinite: the rule's limit there is ri = 90 (SPEC 3.4), returned exactly
  // rather than through atan(inf) so no NaN or rounding can creep in.
  if (outerHalfAngleDeg >= 90.0) return 90.0;
  return degrees(std::atan(kLegacyInnerTangentRatio * std::tan(radians(outerHalfAngleDeg))));
}

double effectiveInnerSpotAngleDeg(const Light& light, Profile profile) {
  if (profile == Profile::Srp && light.innerSpotAngleDeg) return *light.innerSpotAngleDeg;
  return 2.0 * legacyInnerHalfAngleDeg(light.spotAngleDeg / 2.0);
}

SpotFactors lightSpotFactors(const Light& light, Profile profile) {
  if (light.type != LightType::Spot) return {};
  return spotFactors(light.spotAngleDeg, effectiveInnerSpotAngleDeg(light, profile));
}

}  // namespace lighting
