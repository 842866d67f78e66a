#include "baking/bake.h"

#include "baking/bake_cache.h"
#include "lighting/light_math.h"
#include "reference/bvh.h"
#include "reference/parallel_rows.h"
#include "reference/shadow_ray.h"
#include "reference/world_triangles.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>

namespace baking {
namespace {

using lighting::Light;
using lighting::LightType;
using lighting::Vec3;


// SPEC 3.6's falloff(d) for a point or spot light at squared distance
// `rawDistSqr` (unclamped); the inverse-squared forms use 3.2's clamped
// distSqr, so a light on the surface stays finite (at most 1e5 per unit).
double falloff(const Light& light, double rawDistSqr, bool mutantLegacy) {
  const double distSqr = std::max(rawDistSqr, lighting::kMinDistanceSquared);
  lighting::BakeFalloff kind = light.bakeFalloff;
  if (mutantLegacy && kind == lighting::BakeFalloff::InverseSquared) kind = lighting::BakeFalloff::Legacy;
  switch (kind) {
    case lighting::BakeFalloff::InverseSquared:
      return lighting::rangeAttenuation(distSqr, lighting::inverseRangeSquared(light.range)) / distSqr;
    case lighting::BakeFalloff::InverseSquaredNoRange:
      return 1.0 / distSqr;
    case lighting::BakeFalloff::Legacy: {
      // 1 / (1 + 25 d^2 / r^2) for d < r, else 0: at most 1, even at d = 0.
      const double rSq = light.range * light.range;
      if (!(rawDistSqr < rSq)) return 0.0;
      return 1.0 / (1.0 + 25.0 * rawDistSqr / rSq);
    }
  }
  return 0.0;
}

// How deep q lies in a light's range sphere: d^2 / r^2 (< 1 inside), 0 for
// a directional light, which reaches everything.
double reachRatio(const Light& light, const Vec3& q) {
  if (light.type == LightType::Directional) return 0.0;
  const Vec3 ray = light.position - q;
  const double d2 = glm::dot(ray, ray), r2 = light.range * light.range;
  if (r2 > 0) return d2 / r2;
  return d2 == 0 ? 0.0 : std::numeric_limits<double>::infinity();
}

// Texels are float; an irradiance past float's range (intensity 1e38 on the
// surface) is stored as the largest float rather than infinity, so sampling
// it never yields inf - inf = NaN.
float texelValue(double v) {
  constexpr double kLargest = std::numeric_limits<float>::max();
  return v > kLargest ? float(kLargest) : float(v);
}

class TexelBaker {
 public:
  TexelBaker(const lighting::PreparedScene& prepared, const BakeOptions& options)
      : prepared_(prepared), options_(options), world_(reference::buildWorldTriangles(prepared)), bvh_(world_) {
    for (int l = 0; l < int(prepared.scene.lights.size()); ++l)
      if (lighting::isBakedLight(prepared_.scene, prepared_.shadowMask, l)) bakedLights_.push_back(l);
    for (const lighting::ShadowMaskEntry& entry : prepared.shadowMask.entries)
      if (entry.channel >= 0) channelHolders_[std::size_t(entry.channel)].push_back(entry.light);
  }

  // SPEC 3.6's E for one light at q with normal N, without visibility.
  Vec3 irradiance(const Light& light, const Vec3& q, const Vec3& N) const {
    if (light.type == LightType::Directional)  // no falloff, no spot term
      return light.finalColor() * lighting::saturate(glm::dot(N, -light.direction));
    const Vec3 ray = light.position - q;
    const double rawDistSqr = glm::dot(ray, ray);
    const double distSqr = std::max(rawDistSqr, lighting::kMinDistanceSquared);
    const Vec3 L = ray / std::sqrt(distSqr);  // 0 when q is the light's position, never NaN
    const lighting::SpotFactors spot = lighting::lightSpotFactors(light, prepared_.scene.pipeline.profile);
    const double spotAtt = lighting::spotAttenuation(glm::dot(-light.direction, L), spot);
    return light.finalColor() *
           (lighting::saturate(glm::dot(N, L)) * falloff(light, rawDistSqr, options_.mutantLegacyFalloff) * spotAtt);
  }

  // Shadow-mask channel c at q: the visibility of the light holding c. Lights
  // far apart may share a channel (SPEC 5.3); their range spheres do not
  // overlap, so the one whose sphere q lies in (the smallest d^2/r^2) is the
  // one the channel serves there; ties go to the earlier in SPEC 5.3 order.
  double maskChannel(int channel, const Vec3& q, const Vec3& N) const {
    const std::vector<int>& holders = channelHolders_[std::size_t(channel)];
    if (holders.empty()) return 1.0;
    int chosen = holders.front();
    if (holders.size() > 1) {
      double best = std::numeric_limits<double>::infinity();
      for (int l : holders) {
        const double ratio = reachRatio(prepared_.scene.lights[l], q);
        if (ratio < best) best = ratio, chosen = l;
      }
    }
    return reference::lightVisibility(bvh_, prepared_.scene.lights[chosen], q, N);
  }

  lighting::ObjectBake bakeObject(int object) const {
    const lighting::Object& obj = prepared_.scene.objects[object];
    const lighting::ObjectGeometry& geometry = prepared_.objects[object];
    const int n = obj.lightmapResolution;
    const Vec3 N = glm::normalize(geometry.transform.applyToNormal(Vec3(0, 1, 0)));

    lighting::ObjectBake out;
    out.lightmap = {n, std::vector<float>(std::size_t(n) * n * 4)};
    out.shadowMask = {n, std::vector<float>(std::size_t(n) * n * 4)};
    // Each texel depends on nothing but its own centre, so the split over
    // threads cannot change a bit.
    reference::forEachRow(n, options_.threads, [&](int j) {
      for (int i = 0; i < n; ++i) {
        const Vec3 q = geometry.transform.applyToPoint(lighting::planeTexelCentreLocal(obj.mesh, n, i, j));
        Vec3 e(0.0);
        for (int l : bakedLights_) {
          const Light& light = prepared_.scene.lights[std::size_t(l)];
          const Vec3 lit = irradiance(light, q, N);
          if (lit != Vec3(0.0)) e += lit * reference::lightVisibility(bvh_, light, q, N);  // no ray where nothing arrives
        }
        float* lm = &out.lightmap.texels[(std::size_t(j) * n + i) * 4];
        float* sm = &out.shadowMask.texels[(std::size_t(j) * n + i) * 4];
        lm[0] = texelValue(e.x), lm[1] = texelValue(e.y), lm[2] = texelValue(e.z), lm[3] = 1.0f;
        for (int c = 0; c < lighting::kShadowMaskChannels; ++c) sm[c] = float(maskChannel(c, q, N));
      }
    });
    return out;
  }

 private:
  const lighting::PreparedScene& prepared_;
  const BakeOptions& options_;
  reference::WorldTriangles world_;
  reference::Bvh bvh_;
  std::vector<int> bakedLights_;
  std::array<std::vector<int>, lighting::kShadowMaskChannels> channelHolders_;  // in SPEC 5.3 order
};

}  // namespace

std::shared_ptr<const lighting::BakedLighting> bakeScene(const lighting::PreparedScene& prepared,
                                                          const BakeOptions& options) {
  const std::string key = bakeCacheKey(prepared, options);
  if (options.useCache)
    if (auto cached = readCachedBake(key, prepared, options)) return cached;

  const auto start = std::chrono::steady_clock::now();
  auto baked = std::make_shared<lighting::BakedLighting>();
  baked->objects.resize(prepared.scene.objects.size());
  if (prepared.needsBake()) {
    const TexelBaker baker(prepared, options);
    for (int o = 0; o < int(prepared.scene.objects.size()); ++o)
      if (prepared.scene.objects[o].hasLightmap()) baked->objects[o] = baker.bakeObject(o);
  }
  baked->cacheKey = key;
  baked->bakeMilliseconds =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  if (options.useCache) writeCachedBake(*baked, options);
  return baked;
}

std::shared_ptr<const lighting::PreparedScene> prepareBakedScene(lighting::Scene scene, const BakeOptions& options) {
  auto prepared = lighting::prepareScene(std::move(scene));
  if (!prepared->needsBake()) return prepared;
  return withBake(*prepared, bakeScene(*prepared, options));
}

std::shared_ptr<const lighting::PreparedScene> withBake(const lighting::PreparedScene& prepared,
                                                         std::shared_ptr<const lighting::BakedLighting> baked) {
  auto copy = std::make_shared<lighting::PreparedScene>(prepared);
  copy->baked = std::move(baked);
  return copy;
}

}  // namespace baking
