#include "lighting/default_rig.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lighting {
namespace {

// The smallest radius the rig assumes: content of a single point still gets
// lights at a finite distance.
constexpr double kSmallestRadius = 1e-3;
// A point or spot light's range over its distance to the far side of the
// bounding sphere: at that far side rangeAtt (SPEC 3.2) is still 0.64.
constexpr double kRangeMargin = 1.5;
// The spot's outer half-angle over the half-angle the bounding sphere spans
// as seen from it, and the inner cone's share of the outer.
constexpr double kConeMargin = 1.25;
constexpr double kInnerShare = 0.75;
constexpr double kAmbient = 0.03;

double degrees(double radians) { return radians * 180.0 / std::numbers::pi; }

// The camera's frame: forward (towards its target), right and up, each unit;
// a degenerate camera falls back to looking down -Z with +Y up.
struct Frame3 {
  Vec3 forward, right, up;
};

Frame3 cameraFrame(const Camera& camera) {
  Vec3 forward = camera.target - camera.position;
  if (!(glm::length(forward) > 0)) forward = Vec3(0, 0, -1);
  forward = glm::normalize(forward);
  Vec3 right = glm::cross(forward, camera.up);
  if (!(glm::length(right) > 1e-9)) right = glm::cross(forward, std::abs(forward.y) < 0.9 ? Vec3(0, 1, 0) : Vec3(1, 0, 0));
  right = glm::normalize(right);
  return {forward, right, glm::normalize(glm::cross(right, forward))};
}

// A point or spot light at `position`, lighting the sphere (centre, radius):
// the range reaches its far side with room to spare, and the intensity makes
// the light about 1 at the centre (before the cosine and the albedo).
Light localLight(const char* name, LightType type, const Vec3& position, const Vec3& centre, double radius) {
  Light light;
  light.name = name;
  light.type = type;
  light.position = position;
  light.direction = glm::normalize(centre - position);
  const double distance = glm::length(centre - position);
  light.range = kRangeMargin * (distance + radius);
  light.intensity = distance * distance;
  return light;
}

}  // namespace

DefaultRig defaultRig(const Vec3& boundsMin, const Vec3& boundsMax, const Camera& camera) {
  const Vec3 centre = (boundsMin + boundsMax) * 0.5;
  const double radius = std::max(0.5 * glm::length(boundsMax - boundsMin), kSmallestRadius);
  const Frame3 f = cameraFrame(camera);

  DefaultRig rig;
  Light key;
  key.name = "rig-directional";
  key.type = LightType::Directional;
  key.direction = glm::normalize(f.forward * 0.5 - f.up + f.right * 0.4);  // from above, over the left shoulder
  key.intensity = 0.8;
  rig.lights.push_back(key);

  // Fill: on the camera's side, to the left and a little above, 2.5 radii from the centre.
  Light fill = localLight("rig-point", LightType::Point,
                          centre + glm::normalize(-f.forward - f.right * 0.8 + f.up * 0.5) * (2.5 * radius), centre,
                          radius);
  fill.intensity *= 0.6;
  rig.lights.push_back(fill);

  // Rim: to the right and well above, 3 radii out, its cone around the whole sphere.
  Light rim = localLight("rig-spot", LightType::Spot,
                         centre + glm::normalize(-f.forward * 0.6 + f.right + f.up * 1.2) * (3 * radius), centre,
                         radius);
  const double spans = std::asin(std::min(radius / glm::length(centre - rim.position), 1.0));
  rim.spotAngleDeg = std::min(2 * degrees(spans) * kConeMargin, 170.0);
  rim.innerSpotAngleDeg = rim.spotAngleDeg * kInnerShare;
  rim.intensity *= 0.8;
  rig.lights.push_back(rim);

  rig.ambient = Vec3(kAmbient);
  return rig;
}

}  // namespace lighting
