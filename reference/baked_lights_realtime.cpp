#include "reference/baked_lights_realtime.h"

#include "lighting/light_math.h"
#include "reference/parallel_rows.h"
#include "reference/shadow_ray.h"
#include "reference/tolerance_model.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <limits>

namespace reference {

using namespace lighting;
namespace tol = tolerance;

RealtimeBakedLights::RealtimeBakedLights(const PreparedScene& prepared, const Bvh& bvh, int threads)
    : prepared_(prepared), bvh_(bvh) {
  const Scene& scene = prepared.scene;
  for (int l = 0; l < int(scene.lights.size()); ++l)
    if (lighting::isBakedLight(scene, prepared.shadowMask, l)) bakedLights_.push_back(l);

  texelIrradiance_.resize(scene.objects.size());
  for (int o = 0; o < int(scene.objects.size()); ++o) {
    const Object& object = scene.objects[o];
    if (!object.hasLightmap()) continue;
    const int n = object.lightmapResolution;
    const ObjectTransform& transform = prepared.objects[o].transform;
    const Vec3 normal = glm::normalize(transform.applyToNormal(Vec3(0, 1, 0)));
    std::vector<Vec3>& texels = texelIrradiance_[o];
    texels.assign(std::size_t(n) * n, Vec3(0.0));
    forEachRow(n, threads, [&](int j) {
      for (int i = 0; i < n; ++i)
        texels[std::size_t(j) * n + i] =
            irradiance(transform.applyToPoint(planeTexelCentreLocal(object.mesh, n, i, j)), normal);
    });
  }
}

Vec3 RealtimeBakedLights::irradiance(const Vec3& p, const Vec3& N) const {
  const Scene& scene = prepared_.scene;
  Vec3 e(0.0);
  for (int index : bakedLights_) {
    const Light& light = scene.lights[index];
    double attenuation = 0;
    double nl = 0;
    if (light.type == LightType::Directional) {
      // SPEC 3.1 without the mask: baked lights hold no channel.
      nl = saturate(glm::dot(N, -light.direction));
      attenuation = 1;
    } else {
      // SPEC 3.2 as written, whatever the light's bake_falloff says.
      const Vec3 ray = light.position - p;
      const double distSqr = std::max(glm::dot(ray, ray), kMinDistanceSquared);
      const Vec3 L = ray / std::sqrt(distSqr);
      nl = saturate(glm::dot(N, L));
      const double rangeAtt = rangeAttenuation(distSqr, inverseRangeSquared(light.range));
      const double spotAtt = spotAttenuation(glm::dot(-light.direction, L), lightSpotFactors(light, scene.pipeline.profile));
      attenuation = spotAtt * rangeAtt / distSqr;
    }
    if (nl * attenuation == 0) continue;  // no shadow ray for a light that adds nothing
    e += light.finalColor() * (nl * attenuation * lightVisibility(bvh_, light, p, N));
  }
  return e;
}

const Vec3& RealtimeBakedLights::texelIrradiance(int object, int i, int j) const {
  const int n = prepared_.scene.objects[object].lightmapResolution;
  return texelIrradiance_[object][std::size_t(j) * n + i];
}

RealtimeBakedLights::Sample RealtimeBakedLights::sample(int object, const Vec3& p, const Vec3& N,
                                                        const Vec2& uv) const {
  const int n = prepared_.scene.objects[object].lightmapResolution;
  const TexelFootprint f = texelFootprint(n, uv);
  const Vec3& t00 = texelIrradiance(object, f.i0, f.j0);
  const Vec3& t10 = texelIrradiance(object, f.i1, f.j0);
  const Vec3& t01 = texelIrradiance(object, f.i0, f.j1);
  const Vec3& t11 = texelIrradiance(object, f.i1, f.j1);
  // What a correct bake, filtered exactly, would return here.
  const Vec3 interpolated = (t00 * (1 - f.fx) + t10 * f.fx) * (1 - f.fy) + (t01 * (1 - f.fx) + t11 * f.fx) * f.fy;
  const Vec3 largest = glm::max(glm::max(t00, t10), glm::max(t01, t11));
  const Vec3 smallest = glm::min(glm::min(t00, t10), glm::min(t01, t11));

  Sample s;
  s.value = irradiance(p, N);
  s.interpolation = glm::abs(interpolated - s.value);
  for (int c = 0; c < 3; ++c) {
    const double magnitude = std::max(std::abs(largest[c]), std::abs(smallest[c]));
    s.allowance[c] = s.interpolation[c] + filteringErrorBound(largest[c] - smallest[c], magnitude, n) +
                     tol::kTexelStorageRoundingSteps * tol::kUnitRoundoff * magnitude;
  }
  return s;
}

}  // namespace reference
