#include "reference/shadow_ray.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <limits>

namespace reference {

double lightVisibility(const Bvh& bvh, const lighting::Light& light, const Vec3& q, const Vec3& N) {
  if (!light.shadows) return 1.0;
  lighting::Ray ray;
  ray.origin = q + kShadowRayOffset * N;
  double tMax = std::numeric_limits<double>::infinity();
  if (light.type == lighting::LightType::Directional) {
    ray.direction = -light.direction;
  } else {
    const Vec3 toLight = light.position - ray.origin;
    const double distance = glm::length(toLight);
    if (!(distance > 0)) return 1.0;  // the ray starts at the light: nothing lies between
    ray.direction = toLight / distance;
    tMax = std::nextafter(distance, 0.0);  // strictly before the light
  }
  HitFilter anyFace;
  anyFace.frontFacesOnly = false;  // "hits any triangle of the scene"
  return bvh.nearestHit(ray, 0.0, tMax, anyFace) ? 0.0 : 1.0;
}

}  // namespace reference
