// The reference with baked maps (SPEC 3.5, 3.6): the lightmap term, the
// shadow mask per light, the filtering term of the tolerance, demoted lights
// under --ideal, and the comparison against real-time lighting of the baked
// lights (`"expect": {"against": "realtime"}`). Maps are made by hand and
// attached with baking::withBake; expected values are derived in the comments.
#include "baking/bake.h"
#include "lighting/tests/light_builders.h"
#include "reference/baked_lights_realtime.h"
#include "reference/reference_renderer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace reference {
namespace {

using namespace lighting;
using lighting::testing::pointLight;

// The default camera: orthographic, 10 m high, from (0, 10, 0) looking down
// with up = -Z. With a W-pixel square image, column i sees x = -5 + (i + 0.5) 10/W
// and row j sees z = -5 + (j + 0.5) 10/W; on a 10 x 10 plane at the origin
// that is u = (i + 0.5)/W, v = (j + 0.5)/W.
Scene planeScene(int pixels, int lightmapResolution) {
  Scene s;
  s.image = {pixels, pixels};
  Object floor;
  floor.name = "floor";
  floor.mesh.planeSizeX = floor.mesh.planeSizeZ = 10;
  floor.isStatic = lightmapResolution > 0;
  floor.lightmapResolution = lightmapResolution;
  s.objects.push_back(floor);
  return s;
}

// An N x N map with texel (i, j) = f(i, j).
TexelMap mapOf(int n, const std::function<Vec4(int, int)>& f) {
  TexelMap map{n, std::vector<float>(std::size_t(n) * n * 4)};
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const Vec4 t = f(i, j);
      for (int c = 0; c < 4; ++c) map.texels[(std::size_t(j) * n + i) * 4 + c] = float(t[c]);
    }
  return map;
}

TexelMap constantMap(int n, Vec4 value) {
  return mapOf(n, [&](int, int) { return value; });
}

// The scene prepared with hand-made maps for object `object` (the others get none).
std::shared_ptr<const PreparedScene> withMaps(const Scene& s, int object, TexelMap lightmap, TexelMap mask) {
  auto baked = std::make_shared<BakedLighting>();
  baked->objects.resize(s.objects.size());
  baked->objects[object] = {std::move(lightmap), std::move(mask)};
  return baking::withBake(*prepareScene(s), baked);
}

ReferenceImages render(std::shared_ptr<const PreparedScene> prepared, ReferenceOptions options = {}) {
  options.threads = 2;
  return ReferenceRenderer(prepared).render(prepareFrame(prepared, 0), options);
}

Light mixedShadowedDirectional(double intensity) {
  Light l;
  l.type = LightType::Directional;
  l.direction = {0, -1, 0};
  l.intensity = intensity;
  l.mode = LightMode::Mixed;
  l.shadows = true;
  return l;
}

// A 64-pixel view of a plane with albedo (0.5, 1, 1) and a 4 x 4 lightmap
// r(i, j) = (1 + i + 4 j) / 8, g = 2 r, b = 0.25, and no lights.
std::shared_ptr<const PreparedScene> gradientLightmapScene() {
  Scene s = planeScene(64, 4);
  s.objects[0].albedo = {0.5, 1, 1};
  const TexelMap lightmap = mapOf(4, [](int i, int j) {
    const double r = (1 + i + 4 * j) / 8.0;
    return Vec4(r, 2 * r, 0.25, 1);
  });
  return withMaps(s, 0, lightmap, constantMap(4, Vec4(1)));
}

TEST(BakedReference, LightmapIsAlbedoTimesTheBilinearSampleWithAFilteringTolerance) {
  // 64 px, N = 4: pixel (27, 20) has texel coordinates
  //   x = 27.5 / 16 - 0.5 = 1.21875 (texels 1, 2; fx = 7/32),
  //   y = 20.5 / 16 - 0.5 = 0.78125 (texels 0, 1; fy = 25/32).
  // r(i, j) = (1 + i + 4 j) / 8 is linear, so the sample is
  //   (1 + 1.21875 + 4 * 0.78125) / 8 = 0.66796875; g = 2 r; b = 0.25.
  const ReferenceImages img = render(gradientLightmapScene());
  EXPECT_FLOAT_EQ(img.value.at(27, 20, 0), 0.5f * 0.66796875f);
  EXPECT_FLOAT_EQ(img.value.at(27, 20, 1), 2 * 0.66796875f);
  EXPECT_FLOAT_EQ(img.value.at(27, 20, 2), 0.25f);
  EXPECT_EQ(img.value.at(27, 20, 3), 1.0f);

  // Tolerance, red (docs/tolerances.md section 4), with u = 2^-23, one GPU
  // operation's rounding (either neighbour):
  //   filtering: A (2 * 2^-4 * spread + 2 N spread 16u + 6u (|value| + spread))
  //              spread 7/8 - 2/8 = 5/8: 0.5 (0.078125 + 80u + 6u * 1.29296875)
  //   sub-pixel: vertices snap by up to 1/16 pixel (4 bits, the minimum):
  //              along j that moves v by 1/1024, y by 1/256 texel, r by
  //              4/8 * 1/256 = 1/512; along i x by 1/256 texel, r by
  //              1/8 * 1/256 = 1/2048; both at once: 5/2048, times A: 5/4096
  //   roundings: (2 + 1 lightmap add + 1 storage) u |V|
  const double u = 0x1p-23;
  const double red = 0.5 * (2 * 0x1p-4 * 0.625 + 80 * u + 6 * u * (0.66796875 + 0.625)) + 5.0 / 4096 +
                     4 * u * 0.5 * 0.66796875;
  EXPECT_NEAR(img.tolerance.at(27, 20, 0), red, 1e-8);
  EXPECT_NEAR(img.tolerance.at(27, 20, 0), 0.0390625 + 5.0 / 4096, 6e-6);  // the filtering term dominates
  // Green: spread 10/8, A = 1, slope twice red's.
  const double green = 0.15625 + 160 * u + 6 * u * (2 * 0.66796875 + 1.25) + 5.0 / 1024 + 4 * u * 2 * 0.66796875;
  EXPECT_NEAR(img.tolerance.at(27, 20, 1), green, 2e-8);
  // Blue is flat: roundings only.
  EXPECT_GT(img.tolerance.at(27, 20, 2), 0.0f);
  EXPECT_LT(img.tolerance.at(27, 20, 2), 1e-6f);
}

TEST(BakedReference, TheSubPixelTermFollowsTheDevicesBits) {
  // The lightmap of the test above, on a device that keeps 8 sub-pixel bits:
  // a vertex moves by up to 1/256 pixel, 1/16 of the 4-bit step, so the
  // sub-pixel term of red, 5/4096 there, is 5/65536 here (along j r moves by
  // 4/8 * 1/4096, along i by 1/8 * 1/4096, times A = 0.5); the filtering
  // term is the same, 2^-4 weights.
  const auto prepared = gradientLightmapScene();
  ReferenceOptions eightBits;
  eightBits.subPixelPrecisionBits = 8;
  ReferenceOptions fewerThanTheMinimum;  // held to the minimum, 4
  fewerThanTheMinimum.subPixelPrecisionBits = 2;
  const double u = 0x1p-23;
  const double filtering = 0.5 * (2 * 0x1p-4 * 0.625 + 80 * u + 6 * u * (0.66796875 + 0.625)) +
                           4 * u * 0.5 * 0.66796875;
  EXPECT_NEAR(render(prepared, eightBits).tolerance.at(27, 20, 0), filtering + 5.0 / 65536, 1e-8);
  EXPECT_NEAR(render(prepared, fewerThanTheMinimum).tolerance.at(27, 20, 0), filtering + 5.0 / 4096, 1e-8);
}

TEST(BakedReference, AMixedLightOnChannelOneWithStrengthHalfOverAZeroMaskTexelGetsHalf) {
  // Light 0 (directional, first in SPEC 5.3's order) takes channel 0 and
  // overlaps everything, so light 1 takes channel 1. Light 0 has intensity 0.
  Scene s = planeScene(64, 4);
  s.lights.push_back(mixedShadowedDirectional(0));
  Light mixed = pointLight({0, 2, 0}, 10, 1, LightMode::Mixed);
  mixed.shadows = true;
  mixed.shadowStrength = 0.5;
  s.lights.push_back(mixed);
  // Channel 0 at 0.25 and channels 2, 3 at 0.75 catch a wrong channel.
  const TexelMap mask = constantMap(4, Vec4(0.25, 0, 0.75, 0.75));
  const auto prepared = withMaps(s, 0, constantMap(4, Vec4(0, 0, 0, 1)), mask);
  ASSERT_EQ(prepared->shadowMask.channelOfLight, (std::vector<int>{0, 1}));
  const ReferenceImages img = render(prepared);

  // Pixel (32, 32): p = (0.078125, 0, 0.078125), ray = (-0.078125, 2, -0.078125),
  // d^2 = 4.01220703125, N.L = 2 / d, q = d^2 / 100; lerp(1, 0, 0.5) = 0.5.
  const double d2 = 4.01220703125;
  const double unmasked = (2 / std::sqrt(d2)) * std::pow(1 - (d2 / 100) * (d2 / 100), 2) / d2;
  EXPECT_NEAR(img.value.at(32, 32, 0), 0.5 * unmasked, 1e-6);

  // Without the mask's 0 (all ones) the same pixel gets the whole term.
  const ReferenceImages unmaskedImg = render(withMaps(s, 0, constantMap(4, Vec4(0, 0, 0, 1)), constantMap(4, Vec4(1))));
  EXPECT_NEAR(unmaskedImg.value.at(32, 32, 0), unmasked, 1e-6);
}

TEST(BakedReference, AMaskGradientWidensTheToleranceByTheFilteringTerm) {
  // Channel 1 is 0 on texel columns 0-1 and 1 on columns 2-3. Pixel (32, 32)
  // has x = 32.5 / 16 - 0.5 = 1.53125: texels 1 and 2, fx = 0.53125, so
  // mask = 0.53125 and shadowMask = 1 + 0.5 (0.53125 - 1) = 0.765625. The
  // mask's spread is 1: the tolerance gains unmasked * 0.5 * 2 * 2^-4 * 1.
  Scene s = planeScene(64, 4);
  s.lights.push_back(mixedShadowedDirectional(0));
  Light mixed = pointLight({0, 2, 0}, 10, 1, LightMode::Mixed);
  mixed.shadows = true;
  mixed.shadowStrength = 0.5;
  s.lights.push_back(mixed);
  const TexelMap mask = mapOf(4, [](int i, int) { return Vec4(1, i >= 2 ? 1 : 0, 1, 1); });
  const ReferenceImages img = render(withMaps(s, 0, constantMap(4, Vec4(0, 0, 0, 1)), mask));
  const double d2 = 4.01220703125;
  const double unmasked = (2 / std::sqrt(d2)) * std::pow(1 - (d2 / 100) * (d2 / 100), 2) / d2;
  EXPECT_NEAR(img.value.at(32, 32, 0), 0.765625 * unmasked, 1e-6);
  // Filtering: 0.0625 unmasked. Sub-pixel: a vertex snapped by 1/16 pixel
  // moves x by 1/256 texel: the mask by 1/256, the term by 0.5/256 unmasked
  // (~0.002; the mask is constant along y); the light's own gradient and the
  // arithmetic add far less. The filtering term multiplies the largest the
  // unmasked term reaches over the snapping square (float_bound.h), which a
  // 1/16-pixel move changes by under 2 %.
  const float tolerance = img.tolerance.at(32, 32, 0);
  EXPECT_GT(tolerance, 0.0625 * unmasked);
  EXPECT_LT(tolerance, (0.0625 * 1.02 + 0.5 / 256 + 5e-4) * unmasked);
}

TEST(BakedReference, VertexLightsGetNoShadowMask) {
  // Legacy profile: list positions 4-7 are vertex lights. Four bright
  // realtime lights take positions 0-3; the dim mixed light (channel 0)
  // comes fifth by importance, so it is a vertex light, and a mask of 0 on
  // its channel must change nothing (the GPU's vertex stage passes 1).
  Scene s = planeScene(64, 4);
  s.pipeline.profile = Profile::Legacy;
  s.objects[0].mesh.subdivisions = 4;
  for (const Vec3 p : {Vec3(-2, 1, -2), Vec3(2, 1, -2), Vec3(-2, 1, 2), Vec3(2, 1, 2)})
    s.lights.push_back(pointLight(p, 8, 2));
  Light dim = pointLight({0, 1, 0}, 8, 0.1, LightMode::Mixed);
  dim.shadows = true;
  s.lights.push_back(dim);
  const auto zeroMask = withMaps(s, 0, constantMap(4, Vec4(0, 0, 0, 1)), constantMap(4, Vec4(0, 1, 1, 1)));
  ASSERT_EQ(zeroMask->shadowMask.channelOfLight[4], 0);
  const Frame frame = prepareFrame(zeroMask, 0);
  ASSERT_EQ(frame.lightsForObject(0).perVertex, std::vector<int>{4});
  const ReferenceImages masked = render(zeroMask);
  const ReferenceImages ones = render(withMaps(s, 0, constantMap(4, Vec4(0, 0, 0, 1)), constantMap(4, Vec4(1))));
  EXPECT_GT(masked.value.at(32, 32, 0), 0.0f);
  EXPECT_EQ(masked.value.pixels, ones.value.pixels);
}

TEST(BakedReference, AnObjectWithoutMapsIsUnchanged) {
  // Two 5 x 10 planes side by side: the left one (x < 0) has a lightmap of
  // constant (1, 0.5, 0.25), the right one none. The right half must match
  // the scene in which neither has maps; the left half gains A * lightmap.
  Scene s = planeScene(64, 0);
  s.objects[0].mesh.planeSizeX = 5;
  s.objects[0].transform.translate = {-2.5, 0, 0};
  Object right = s.objects[0];
  right.name = "right";
  right.transform.translate = {2.5, 0, 0};
  s.objects.push_back(right);
  s.lights.push_back(pointLight({0.3, 1.5, -0.2}, 8, 2));
  const ReferenceImages plain = render(prepareScene(s));
  s.objects[0].isStatic = true;
  s.objects[0].lightmapResolution = 4;
  const ReferenceImages lit = render(withMaps(s, 0, constantMap(4, Vec4(1, 0.5, 0.25, 1)), constantMap(4, Vec4(1))));
  for (int j = 4; j < 60; ++j) {
    for (int i = 36; i < 60; ++i) {
      for (int c = 0; c < 4; ++c) ASSERT_EQ(lit.value.at(i, j, c), plain.value.at(i, j, c)) << i << "," << j;
      for (int c = 0; c < 3; ++c) ASSERT_EQ(lit.tolerance.at(i, j, c), plain.tolerance.at(i, j, c)) << i << "," << j;
    }
    for (int i = 4; i < 28; ++i) {
      ASSERT_NEAR(lit.value.at(i, j, 0), plain.value.at(i, j, 0) + 1.0f, 1e-5) << i << "," << j;
      ASSERT_NEAR(lit.value.at(i, j, 2), plain.value.at(i, j, 2) + 0.25f, 1e-5) << i << "," << j;
    }
  }
}

TEST(BakedReference, IdealKeepsDemotedLightsBaked) {
  // Five mixed shadowed directional lights all overlap: channels 0-3 go to
  // lights 0-3 (scene order), light 4 is demoted. Only light 4 has intensity:
  // it lives in the lightmap (here 0), so neither the budgeted nor the
  // --ideal reference may light it in real time.
  Scene s = planeScene(32, 4);
  for (int k = 0; k < 5; ++k) s.lights.push_back(mixedShadowedDirectional(k == 4 ? 1 : 0));
  const auto prepared = withMaps(s, 0, constantMap(4, Vec4(0, 0, 0, 1)), constantMap(4, Vec4(1)));
  ASSERT_TRUE(prepared->shadowMask.demotedLight[4]);
  ReferenceOptions ideal;
  ideal.ideal = true;
  EXPECT_EQ(render(prepared).value.at(16, 16, 0), 0.0f);
  EXPECT_EQ(render(prepared, ideal).value.at(16, 16, 0), 0.0f);
}

// --- against real time ------------------------------------------------------

// 60 px over 10 m and N = 4: pixel 15 t + 7 has its centre on texel t's
// centre ((t + 0.5) / 4 = (15 t + 7.5) / 60), e.g. pixel 22 at x = -1.25.
Scene realtimeScene() {
  Scene s = planeScene(60, 4);
  s.lights.push_back(pointLight({0, 2, 0}, 10, 4, LightMode::Baked));
  s.expect.against = CompareAgainst::Realtime;
  return s;
}

ReferenceOptions realtimeOptions() {
  ReferenceOptions o;
  o.bakedLightsRealtime = true;
  return o;
}

// SPEC 3.2 for the light above, at (x, 0, z) with N = +Y: 4 N.L rangeAtt / d^2.
double pointAt(double x, double z) {
  const double d2 = x * x + 4 + z * z;
  return 4 * (2 / std::sqrt(d2)) * std::pow(1 - (d2 / 100) * (d2 / 100), 2) / d2;
}

TEST(BakedReferenceRealtime, ValuesAreSpec32AtPixelCentres) {
  const Scene s = realtimeScene();
  const ReferenceImages img = render(withMaps(s, 0, constantMap(4, Vec4(0, 0, 0, 1)), constantMap(4, Vec4(1))),
                                     realtimeOptions());
  // (22, 22): p = (-1.25, 0, -1.25), d^2 = 7.125: 4 (2/sqrt 7.125)(1 - 0.07125^2)^2 / 7.125.
  EXPECT_NEAR(img.value.at(22, 22, 0), 4 * (2 / std::sqrt(7.125)) * std::pow(1 - 0.07125 * 0.07125, 2) / 7.125, 1e-6);
  // (29, 29): x = z = -5 + 29.5/6 = -1/12; (41, 10): x = 1 + 5/6 - ... by the formula above.
  EXPECT_NEAR(img.value.at(29, 29, 0), pointAt(-1.0 / 12, -1.0 / 12), 1e-6);
  EXPECT_NEAR(img.value.at(41, 10, 1), pointAt(-5 + 41.5 / 6, -5 + 10.5 / 6), 1e-6);
  // The lightmap (all 0 here) is not read.
  EXPECT_GT(img.value.at(41, 10, 1), 0.05f);
}

TEST(BakedReferenceRealtime, InterpolationAllowanceIsZeroAtTexelCentresAndPositiveBetween) {
  const Scene s = realtimeScene();
  const auto prepared = withMaps(s, 0, constantMap(4, Vec4(0, 0, 0, 1)), constantMap(4, Vec4(1)));
  const WorldTriangles world = buildWorldTriangles(*prepared);
  const Bvh bvh(world);
  const RealtimeBakedLights realtime(*prepared, bvh, 2);
  const Vec3 up(0, 1, 0);
  // Texel (1, 1)'s centre: uv (0.375, 0.375), p = (-1.25, 0, -1.25).
  const auto atCentre = realtime.sample(0, {-1.25, 0, -1.25}, up, {0.375, 0.375});
  EXPECT_NEAR(atCentre.interpolation.r, 0, 1e-12);
  // Midway between the four texels (±1.25, ±1.25), uv (0.5, 0.5): the
  // bilinear value is the mean of four equal corners, pointAt(1.25, 1.25),
  // against E(0, 0, 0) = 4 * (1 - 0.0016)^2 / 4.
  const auto between = realtime.sample(0, {0, 0, 0}, up, {0.5, 0.5});
  const double expected = std::abs(pointAt(1.25, 1.25) - std::pow(1 - 0.0016, 2));
  EXPECT_NEAR(between.interpolation.r, expected, 1e-12);
  EXPECT_GT(between.interpolation.r, 0.1);
  // The four corners are equal: the filtering term is roundings only.
  EXPECT_LT(between.allowance.r - between.interpolation.r, 1e-6);

  // In the image: the pixel on the texel centre keeps a tight tolerance (the
  // allowance is taken over the sub-pixel shifts too, 1/16 pixel = 1/96 m
  // away, where it grows as the square of the distance from the centre:
  // about 4 x 2e-3 here, 2e-3 being its value 1/192 m away); the one near the
  // middle of the cell gets the whole gap between the flat bilinear value and
  // the peak under the light.
  const ReferenceImages img = render(prepared, realtimeOptions());
  EXPECT_LT(img.tolerance.at(22, 22, 0), 1e-2f);
  EXPECT_GT(img.tolerance.at(29, 29, 0), 0.9 * std::abs(pointAt(1.25, 1.25) - pointAt(-1.0 / 12, -1.0 / 12)));
}

TEST(BakedReferenceRealtime, ShadowedBakedLightIsZeroInTheShadow) {
  // A baked directional light with shadows travelling (1, -1, 0)/sqrt2 and a
  // 2 x 1 x 2 box with y in [0.5, 1.5], x and z in [-1, 1]: the plane is in
  // shadow for x in [-0.5, 2.5], |z| < 1. Pixel (40, 29) sees
  // (1.75, 0, -1/12): shadow, 0. Pixel (51, 29) sees x = 3.58: lit, 3 N.L = 3/sqrt2.
  Scene s = planeScene(60, 8);
  Object box;
  box.name = "box";
  box.mesh.type = MeshType::Box;
  box.mesh.boxSize = {2, 1, 2};
  box.transform.translate = {0, 1, 0};
  s.objects.push_back(box);
  Light sun;
  sun.type = LightType::Directional;
  sun.direction = glm::normalize(Vec3(1, -1, 0));
  sun.intensity = 3;
  sun.mode = LightMode::Baked;
  sun.shadows = true;
  s.lights.push_back(sun);
  const ReferenceImages img = render(withMaps(s, 0, constantMap(8, Vec4(0, 0, 0, 1)), constantMap(8, Vec4(1))),
                                     realtimeOptions());
  EXPECT_EQ(img.value.at(40, 29, 0), 0.0f);
  EXPECT_NEAR(img.value.at(51, 29, 0), 3 / std::sqrt(2.0), 1e-6);
}

// A real bake against the real-time reference: an inverse-squared bake,
// sampled exactly, passes everywhere; a legacy-falloff bake fails.
int failingPixelsAgainstRealtime(BakeFalloff falloff) {
  Scene s = planeScene(60, 16);
  Light light = pointLight({0.4, 1.5, -0.3}, 6, 4, LightMode::Baked);
  light.bakeFalloff = falloff;
  s.lights.push_back(light);
  baking::BakeOptions bake;
  bake.useCache = false;
  bake.threads = 2;
  const auto prepared = baking::prepareBakedScene(s, bake);
  const ReferenceImages lightmapped = render(prepared);
  const ReferenceImages realtime = render(prepared, realtimeOptions());
  int failing = 0;
  for (int j = 0; j < 60; ++j)
    for (int i = 0; i < 60; ++i) {
      if (realtime.value.at(i, j, 3) == 0) continue;
      for (int c = 0; c < 3; ++c)
        if (std::abs(lightmapped.value.at(i, j, c) - realtime.value.at(i, j, c)) > realtime.tolerance.at(i, j, c)) {
          ++failing;
          break;
        }
    }
  return failing;
}

TEST(BakedReferenceRealtime, AnInverseSquaredBakePassesALegacyBakeFails) {
  EXPECT_EQ(failingPixelsAgainstRealtime(BakeFalloff::InverseSquared), 0);
  EXPECT_GT(failingPixelsAgainstRealtime(BakeFalloff::Legacy), 100);
}

}  // namespace
}  // namespace reference
