#include "lighting/brdf.h"

#include "lighting/light_math.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace lighting {

MaterialBrdf materialBrdf(const Object& object) {
  MaterialBrdf brdf;
  if (object.brdf == Brdf::Lambert) {
    brdf.diffuse = object.albedo;
    return brdf;
  }
  const double oneMinusReflectivity = (1.0 - kMinReflectivity) * (1.0 - object.metallic);
  brdf.diffuse = object.albedo * oneMinusReflectivity;
  brdf.specular = Vec3(kMinReflectivity) + (object.albedo - Vec3(kMinReflectivity)) * object.metallic;  // lerp
  brdf.roughness = square(1.0 - object.smoothness);
  brdf.lobe = true;
  return brdf;
}

Vec3 viewDirection(const CameraView& view, const Vec3& p) {
  if (view.camera.projection == Projection::Orthographic) return -view.forward;
  return glm::normalize(view.camera.position - p);
}

Vec3 safeNormalize(const Vec3& v) {
  return v * (1.0 / std::sqrt(std::max(glm::dot(v, v), kSafeNormalizeFloor)));
}

double specularStrength(const Vec3& N, const Vec3& V, const Vec3& L, double roughness) {
  const Vec3 H = safeNormalize(L + V);
  const double nh2 = square(saturate(glm::dot(N, H)));
  const double lh2 = square(saturate(glm::dot(L, H)));
  const double r2 = square(roughness);
  const double d2 = square(nh2 * (r2 - 1.0) + kLobeDenominatorOffset);
  return r2 / (d2 * std::max(kMinLh2, lh2) * (roughness * 4.0 + 2.0));
}

}  // namespace lighting
