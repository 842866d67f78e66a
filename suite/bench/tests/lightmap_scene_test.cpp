// The lightmap benchmark scene (suite/bench/bench_scenes.h) and the premise
// of the lightmap-N modes: the baked map, sampled as SPEC 3.6 says, converges
// to the real-time lighting of the same lights as N grows, and the shadowed
// light's shadow is on the plane. The exact irradiance is written out here
// from SPEC 3.2, not taken from the baker or lighting/light_math.
#include "baking/bake.h"
#include "lighting/baked_lighting.h"
#include "suite/bench/bench_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace {

using namespace lighting;

// SPEC 3.2 for a point light on the plane y = 0 (normal +y): finalColor *
// saturate(N.L) * rangeAtt / distSqr, no shadow.
Vec3 exactIrradiance(const Scene& scene, const Vec3& p) {
  Vec3 sum(0.0);
  for (const Light& l : scene.lights) {
    const Vec3 ray = l.position - p;
    const double distSqr = std::max(ray.x * ray.x + ray.y * ray.y + ray.z * ray.z, 1e-5);
    const double nl = std::clamp(ray.y / std::sqrt(distSqr), 0.0, 1.0);
    const double q = std::clamp(1.0 - std::pow(distSqr / (l.range * l.range), 2), 0.0, 1.0);
    sum += l.color * l.intensity * (nl * q * q / distSqr);
  }
  return sum;
}

struct MapError {
  double rmse = 0, maxAbs = 0;
};

// The lightmap's bilinear sample against the exact irradiance at the centres
// of a 251 x 141 grid over the plane (which fills the view).
MapError errorOfBake(int resolution, bool shadows) {
  bench::LightmapSpec spec;
  spec.resolution = resolution;
  spec.shadows = shadows;
  const Scene scene = bench::lightmapScene(spec, "test");
  baking::BakeOptions noCache;
  noCache.useCache = false;
  const auto prepared = baking::prepareBakedScene(scene, noCache);
  const Object& plane = scene.objects.front();
  const ObjectBake* bake = prepared->bakeOf(0);
  EXPECT_NE(bake, nullptr);
  if (!bake) return {};
  MapError e;
  double squares = 0;
  const int w = 251, h = 141;  // not a multiple of any N: samples fall anywhere between texel centres
  for (int j = 0; j < h; ++j) {
    for (int i = 0; i < w; ++i) {
      const Vec3 local((i + 0.5) / w * plane.mesh.planeSizeX - plane.mesh.planeSizeX / 2, 0,
                       (j + 0.5) / h * plane.mesh.planeSizeZ - plane.mesh.planeSizeZ / 2);
      const Vec4 baked = sampleBilinear(bake->lightmap, planeLightmapUv(plane.mesh, local)).value;
      const Vec3 exact = exactIrradiance(scene, local);  // the plane sits at the origin
      for (int c = 0; c < 3; ++c) {
        const double d = baked[c] - exact[c];
        squares += d * d;
        e.maxAbs = std::max(e.maxAbs, std::abs(d));
      }
    }
  }
  e.rmse = std::sqrt(squares / (3.0 * w * h));
  return e;
}

TEST(LightmapScene, BakedAndRealtimeVariantsHoldTheSameLights) {
  bench::LightmapSpec spec;
  spec.resolution = 32;
  EXPECT_FALSE(bench::lightmapScene(spec, "unshadowed").lights.back().shadows);
  spec.shadows = true;
  const Scene baked = bench::lightmapScene(spec, "baked");
  spec.baked = false;
  const Scene realtime = bench::lightmapScene(spec, "realtime");
  ASSERT_EQ(baked.lights.size(), 5u);
  ASSERT_EQ(realtime.lights.size(), baked.lights.size());
  EXPECT_TRUE(baked.objects.front().hasLightmap());
  EXPECT_EQ(baked.objects.front().lightmapResolution, 32);
  EXPECT_FALSE(realtime.objects.front().hasLightmap());
  int shadowed = 0;
  for (std::size_t l = 0; l < baked.lights.size(); ++l) {
    EXPECT_EQ(baked.lights[l].mode, LightMode::Baked);
    EXPECT_EQ(realtime.lights[l].mode, LightMode::Realtime);
    EXPECT_EQ(baked.lights[l].bakeFalloff, BakeFalloff::InverseSquared);
    EXPECT_EQ(baked.lights[l].position, realtime.lights[l].position);
    EXPECT_EQ(baked.lights[l].finalColor(), realtime.lights[l].finalColor());
    shadowed += baked.lights[l].shadows ? 1 : 0;
  }
  EXPECT_EQ(shadowed, 1);
}

// Bilinear interpolation of a smooth function errs by O(h^2): from 16 to 128
// texels the error must fall by far more than the 2x asked here.
TEST(LightmapScene, BakeConvergesToRealTimeWithoutShadows) {
  const MapError coarse = errorOfBake(16, false), mid = errorOfBake(64, false), fine = errorOfBake(128, false);
  EXPECT_GT(coarse.rmse, 0.01);  // 16 texels miss the pools of the low lights
  EXPECT_LT(mid.rmse, 0.5 * coarse.rmse);
  EXPECT_LT(fine.rmse, 0.5 * mid.rmse);
  EXPECT_LT(fine.maxAbs, coarse.maxAbs);
}

// With the shadowed light the bake differs from real time (which draws no
// shadow) by the shadow at every resolution: the error stops falling.
TEST(LightmapScene, ShadowLeavesAnErrorFloor) {
  const MapError unshadowed = errorOfBake(128, false), shadowed = errorOfBake(128, true);
  EXPECT_GT(shadowed.rmse, unshadowed.rmse);
  EXPECT_GT(shadowed.maxAbs, 0.05);  // the shadowed light gives about 0.1 where the shadow falls
}

}  // namespace
