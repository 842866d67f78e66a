// Every backend and driver pair samples an object's baked maps (SPEC 3.5,
// 3.6) as the model says: bilinearly, clamped to the edge, texel (i, j) at
// UV ((i + 0.5) / N, (j + 0.5) / N), the lightmap added to the light sum and
// the shadow mask's channel c attenuating the mixed light that holds c by
// lerp(1, mask[c], strength). The maps are built here by hand and attached
// with baking::withBake, so nothing of the baker is under test; every
// expected value is computed here from the texels and SPEC 3.2 written out.
//
// The view: a 4 x 4 plane at the origin seen straight down by an
// orthographic camera whose frame is exactly the plane, so pixel (i, j) of
// the W x W image has its centre at UV ((i + 0.5) / W, (j + 0.5) / W) (the
// camera's up is -Z: row 0 is the plane's -Z edge, v = 0; column 0 its -X
// edge, u = 0). Every pixel centre is on the plane. W = 17 N, so the pixel
// i = 17 k + 8 has its centre exactly at texel k's centre.
//
// Allowance per channel: the texture-filtering term of SPEC 7, 2^-4 of the
// spread (max - min) of the four texels blended, once per filtering
// direction (2 * 2^-4), plus float slack; at texel centres the weights are
// exactly 0 and 1, so there only the slack.
#include "backends/backend.h"
#include "backends/tests/backend_combinations.h"
#include "baking/bake.h"
#include "lighting/frame.h"
#include "scene_input/scene_loader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <string>

namespace {

using backends::testing::Combination;

constexpr int kMapResolution = 4;                        // N
constexpr int kPixelsPerTexel = 17;                      // odd: pixel centres hit texel centres
constexpr int kImageSize = kMapResolution * kPixelsPerTexel;  // 68
constexpr double kFilteringPrecision = 0x1p-4;           // SPEC 7: the Vulkan minimum
constexpr double kFilteringDirections = 2;               // u and v each round their weight
// float32 slack on a sampled texel (a few roundings of the weights and sums).
constexpr double kTexelRelativeSlack = 1e-5;
// float32 slack on SPEC 3.2 evaluated in the shader: distSqr, inversesqrt, the
// range window and the products, each within a few 2^-24.
constexpr double kLightRelativeSlack = 1e-4;
constexpr double kAbsoluteSlack = 1e-7;
constexpr int kReportedFailures = 5;

// The scene: one static 4 x 4 plane with a 4 x 4 lightmap, ambient 0; the
// lights are the caller's.
std::string sceneJson(const std::string& albedo, const std::string& lights) {
  return R"({
  "lightcts": 1, "name": "baked-maps-sampling",
  "image": {"width": )" + std::to_string(kImageSize) + R"(, "height": )" + std::to_string(kImageSize) + R"(},
  "camera": {"position": [0, 10, 0], "target": [0, 0, 0], "up": [0, 0, -1],
             "projection": "orthographic", "height": 4, "near": 0.1, "far": 100},
  "objects": [{"name": "floor", "mesh": {"type": "plane", "size": [4, 4], "subdivisions": 1},
               "material": {"albedo": )" + albedo + R"(},
               "static": true, "lightmap_resolution": )" + std::to_string(kMapResolution) + R"(}],
  "lights": [)" + lights + R"(]
})";
}

using Texel = std::array<double, 4>;

lighting::TexelMap makeMap(const std::function<Texel(int i, int j)>& texel) {
  lighting::TexelMap map;
  map.resolution = kMapResolution;
  for (int j = 0; j < kMapResolution; ++j)
    for (int i = 0; i < kMapResolution; ++i)
      for (double v : texel(i, j)) map.texels.push_back(float(v));
  return map;
}

Texel texelOf(const lighting::TexelMap& map, int i, int j) {
  i = std::clamp(i, 0, map.resolution - 1);
  j = std::clamp(j, 0, map.resolution - 1);
  const float* t = &map.texels[(std::size_t(j) * map.resolution + i) * 4];
  return {t[0], t[1], t[2], t[3]};
}

// Bilinear, clamp to edge, written out: texel centres at (k + 0.5) / N.
struct Filtered {
  Texel value{};
  Texel spread{};  // max - min of the four texels blended, per channel
};

Filtered bilinear(const lighting::TexelMap& map, double u, double v) {
  const double x = u * map.resolution - 0.5;
  const double y = v * map.resolution - 0.5;
  const int i0 = int(std::floor(x));
  const int j0 = int(std::floor(y));
  const double fx = x - i0;
  const double fy = y - j0;
  const Texel t00 = texelOf(map, i0, j0), t10 = texelOf(map, i0 + 1, j0);
  const Texel t01 = texelOf(map, i0, j0 + 1), t11 = texelOf(map, i0 + 1, j0 + 1);
  Filtered f;
  for (int c = 0; c < 4; ++c) {
    const double top = t00[c] + (t10[c] - t00[c]) * fx;
    const double bottom = t01[c] + (t11[c] - t01[c]) * fx;
    f.value[c] = top + (bottom - top) * fy;
    f.spread[c] = std::max({t00[c], t10[c], t01[c], t11[c]}) - std::min({t00[c], t10[c], t01[c], t11[c]});
  }
  return f;
}

double pixelCentreUv(int pixel) { return (pixel + 0.5) / kImageSize; }
bool atTexelCentre(int pixel) { return pixel % kPixelsPerTexel == kPixelsPerTexel / 2; }
int texelUnder(int pixel) { return pixel / kPixelsPerTexel; }

// What one pixel channel should be, and how far from it a correct render may be.
struct Expected {
  double value = 0;
  double allowed = 0;
};

// Compares every pixel's RGB against `expected` and A against 1.
void compareEveryPixel(const std::string& what, const imaging::Image& image,
                       const std::function<Expected(int i, int j, int c)>& expected) {
  ASSERT_EQ(image.width, kImageSize) << what;
  ASSERT_EQ(image.height, kImageSize) << what;
  ASSERT_EQ(image.channels, 4) << what;
  int failures = 0;
  double worstRatio = 0;
  for (int j = 0; j < kImageSize; ++j)
    for (int i = 0; i < kImageSize; ++i) {
      for (int c = 0; c < 3; ++c) {
        const Expected e = expected(i, j, c);
        const double rendered = image.at(i, j, c);
        const double difference = std::abs(rendered - e.value);
        if (e.allowed > 0) worstRatio = std::max(worstRatio, difference / e.allowed);
        if (!(difference <= e.allowed) && ++failures <= kReportedFailures)
          ADD_FAILURE() << what << ": pixel (" << i << ", " << j << ") channel " << c << ": rendered " << rendered
                        << ", expected " << e.value << ", difference " << difference << " (allowed " << e.allowed
                        << ")";
      }
      if (image.at(i, j, 3) != 1.0f && ++failures <= kReportedFailures)
        ADD_FAILURE() << what << ": pixel (" << i << ", " << j << ") A = " << image.at(i, j, 3);
    }
  EXPECT_EQ(failures, 0) << what << ": failing channels (first " << kReportedFailures << " shown)";
  std::printf("[ %s ] largest difference / allowed: %.3g\n", what.c_str(), worstRatio);
}

// Texel values that differ from every neighbour in every channel.
lighting::TexelMap firstLightmap() {
  return makeMap([](int i, int j) -> Texel {
    return {0.25 + 0.125 * (i + 4 * j), 3.0 - 0.15 * (j + 4 * i), 1.0 + 0.3 * i - 0.2 * j + 0.05 * i * j, 1.0};
  });
}
lighting::TexelMap secondLightmap() {
  return makeMap([](int i, int j) -> Texel {
    return {2.0 - 0.1 * (i * i + j), 0.5 + 0.2 * j, 0.75 + 0.4 * ((i + j) % 3), 1.0};
  });
}
lighting::TexelMap allOnesMask() {
  return makeMap([](int, int) -> Texel { return {1, 1, 1, 1}; });
}

std::shared_ptr<const lighting::BakedLighting> bakeOf(lighting::TexelMap lightmap, lighting::TexelMap mask) {
  auto baked = std::make_shared<lighting::BakedLighting>();
  baked->objects.push_back({std::move(lightmap), std::move(mask)});
  baked->cacheKey = "hand-made";
  return baked;
}

class BakedMaps : public ::testing::TestWithParam<Combination> {};

// Albedo 1, no lights, ambient 0: the image is the lightmap's RGB.
void checkLightmap(const std::string& what, const imaging::Image& image, const lighting::TexelMap& map) {
  compareEveryPixel(what, image, [&](int i, int j, int c) {
    if (atTexelCentre(i) && atTexelCentre(j)) {
      const double texel = texelOf(map, texelUnder(i), texelUnder(j))[c];
      return Expected{texel, kTexelRelativeSlack * std::abs(texel)};
    }
    const Filtered f = bilinear(map, pixelCentreUv(i), pixelCentreUv(j));
    return Expected{f.value[c], kFilteringDirections * kFilteringPrecision * f.spread[c] +
                                    kTexelRelativeSlack * std::abs(f.value[c]) + kAbsoluteSlack};
  });
}

TEST_P(BakedMaps, LightmapIsSampledBilinearlyAndReuploadedWhenTheBakeChanges) {
  std::string whyNot;
  const auto backend = backends::testing::createOrNull(GetParam(), whyNot);
  if (!backend) GTEST_SKIP() << whyNot;
  const auto plain = lighting::prepareScene(scene_input::loadSceneText(sceneJson("[1, 1, 1]", ""), "lightmap.json"));
  const auto first = baking::withBake(*plain, bakeOf(firstLightmap(), allOnesMask()));
  const auto second = baking::withBake(*plain, bakeOf(secondLightmap(), allOnesMask()));
  ASSERT_TRUE(lighting::prepareFrame(first, 0).features.lightmap);

  checkLightmap("first bake", backend->render(lighting::prepareFrame(first, 0)), firstLightmap());
  // A new bake of the same scene (what a CPU mutant hands over) is uploaded
  // anew, and going back uploads the first again.
  checkLightmap("second bake", backend->render(lighting::prepareFrame(second, 0)), secondLightmap());
  checkLightmap("first bake again", backend->render(lighting::prepareFrame(first, 0)), firstLightmap());
}

// Two mixed directional lights of intensity 0 take channels 0 and 1 (SPEC
// 5.3: directional lights first, in scene order; a directional light
// overlaps everything), so the point light takes channel 2; the mask holds a
// 0/1 checkerboard in channel 2 and its opposite in 0, 1 and 3, so reading
// another channel gives the opposite image.
constexpr const char* kMaskLights = R"(
  {"name": "d0", "type": "directional", "direction": [0, -1, 0], "color": [1, 1, 1], "intensity": 0,
   "mode": "mixed", "shadows": true, "shadow_strength": 1},
  {"name": "d1", "type": "directional", "direction": [0, -1, 0], "color": [1, 1, 1], "intensity": 0,
   "mode": "mixed", "shadows": true, "shadow_strength": 1},
  {"name": "p", "type": "point", "position": [0, 2, 0], "range": 10, "color": [1, 0.8, 0.6], "intensity": 3,
   "mode": "mixed", "shadows": true, "shadow_strength": 0.5})";
constexpr int kMaskChannel = 2;
constexpr double kStrength = 0.5;
constexpr std::array<double, 3> kAlbedo{0.9, 0.7, 0.5};
constexpr std::array<double, 3> kFinalColor{3.0, 2.4, 1.8};  // color * intensity
constexpr double kLightHeight = 2, kLightRange = 10;

double checkerboard(int i, int j) { return (i + j) % 2 == 0 ? 1.0 : 0.0; }

// SPEC 3.2 for the point light straight above the plane's centre, at the
// plane point (x, 0, z) with N = +Y, without the shadow mask: albedo included.
double unmaskedPointLight(double x, double z, int c) {
  const double distSqr = std::max(x * x + kLightHeight * kLightHeight + z * z, 1e-5);
  const double cosine = std::clamp(kLightHeight / std::sqrt(distSqr), 0.0, 1.0);  // dot(N, L), L = ray / |ray|
  const double invRangeSq = 1.0 / std::max(kLightRange * kLightRange, 1e-5);
  const double window = std::clamp(1.0 - (distSqr * invRangeSq) * (distSqr * invRangeSq), 0.0, 1.0);
  const double rangeAtt = window * window;
  return kAlbedo[c] * kFinalColor[c] * cosine * rangeAtt / distSqr;  // spotAtt = 1 for a point light
}

TEST_P(BakedMaps, ShadowMaskChannelAttenuatesItsMixedLightByItsStrength) {
  std::string whyNot;
  const auto backend = backends::testing::createOrNull(GetParam(), whyNot);
  if (!backend) GTEST_SKIP() << whyNot;
  const auto plain =
      lighting::prepareScene(scene_input::loadSceneText(sceneJson("[0.9, 0.7, 0.5]", kMaskLights), "mask.json"));
  ASSERT_EQ(plain->shadowMask.channelOfLight, (std::vector<int>{0, 1, kMaskChannel}));

  const lighting::TexelMap mask = makeMap([](int i, int j) -> Texel {
    const double m = checkerboard(i, j);
    return {1 - m, 1 - m, m, 1 - m};
  });
  const lighting::TexelMap noLight = makeMap([](int, int) -> Texel { return {0, 0, 0, 1}; });
  const auto prepared = baking::withBake(*plain, bakeOf(noLight, mask));
  const lighting::Frame frame = lighting::prepareFrame(prepared, 0);
  ASSERT_TRUE(frame.features.shadowMask);

  compareEveryPixel(GetParam().suffix + " shadow mask", backend->render(frame), [&](int i, int j, int c) {
    const double u = pixelCentreUv(i), v = pixelCentreUv(j);
    const double light = unmaskedPointLight(4 * u - 2, 4 * v - 2, c);  // x = sx (u - 0.5), z = sz (v - 0.5)
    if (atTexelCentre(i) && atTexelCentre(j)) {
      const double value = light * (1 + (checkerboard(texelUnder(i), texelUnder(j)) - 1) * kStrength);
      return Expected{value, kLightRelativeSlack * value + kAbsoluteSlack};
    }
    const Filtered f = bilinear(mask, u, v);
    const double attenuation = 1 + (f.value[kMaskChannel] - 1) * kStrength;  // lerp(1, mask[c], s)
    const double value = light * attenuation;
    return Expected{value, light * kStrength * kFilteringDirections * kFilteringPrecision * f.spread[kMaskChannel] +
                               kLightRelativeSlack * value + kAbsoluteSlack};
  });
}

// A scene with a lightmap drawn without its bake is refused, not drawn dark.
TEST_P(BakedMaps, ASceneWithoutItsBakeIsRefused) {
  std::string whyNot;
  const auto backend = backends::testing::createOrNull(GetParam(), whyNot);
  if (!backend) GTEST_SKIP() << whyNot;
  const auto unbaked = lighting::prepareScene(scene_input::loadSceneText(sceneJson("[1, 1, 1]", ""), "unbaked.json"));
  EXPECT_THROW(backend->render(lighting::prepareFrame(unbaked, 0)), std::logic_error);
}

INSTANTIATE_TEST_SUITE_P(EveryCombination, BakedMaps, ::testing::ValuesIn(backends::testing::allCombinations()),
                         backends::testing::combinationTestName);

}  // namespace
