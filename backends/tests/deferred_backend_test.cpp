// Every backend and driver pair draws the deferred path (SPEC 3.7) as the
// forward path draws the same lights, within what each light buffer format
// allows:
//   hdr32: RGBA32F everywhere, so only float32 differences remain (the
//          position reconstructed from the stored window depth instead of the
//          interpolated one): 1e-4 relative + 1e-6 absolute per channel;
//   hdr16: each additive blend rounds the running sum to half (10 stored
//          mantissa bits); the bound is derived below;
//   ldr8:  exp2(-c) stored in 8 bits and decoded by -log2(max(x, 1/255)):
//          checked against values derived here by hand, saturation included.
// And the camera inside a point light's volume: back faces with the reversed
// depth test light the surface exactly once; the mutant
// point-volume-outside-only (front faces, LESS_OR_EQUAL) leaves it dark. A
// volume reaching past the far plane still lights the surface (depth clamp),
// and switching light buffer formats on one backend leaves nothing stale.
//
// The forward render is the independent path here: it shares the lighting
// functions but none of the G-buffer, volumes, blending or composite.
#include "backends/backend.h"
#include "backends/tests/backend_combinations.h"
#include "lighting/frame.h"
#include "scene_input/scene_loader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace {

using backends::testing::Combination;

constexpr int kImageSize = 64;
constexpr int kReportedFailures = 5;

// hdr32 against forward (the brief's bound; float32 arithmetic is ~1e-7).
constexpr double kHdr32Relative = 1e-4;
constexpr double kHdr32Absolute = 1e-6;

// hdr16: a half has an 11-bit significand, and the APIs leave the rounding
// of a conversion to half open (to nearest or toward zero), so a rounding is
// within 2^-10 of the value (the model's kHalfRounding). Per light draw two
// roundings can touch the sum: the fragment's output converted to half
// before the blend, and the blended sum written back; each is within 2^-10
// of a value no larger than the final sum (every term is >= 0), so with n
// lights |deferred - exact| <= 2 n 2^-10 S. Values below half's smallest
// normal (2^-14) round to a multiple of 2^-24: within one such step.
constexpr double kHalfUnitRoundoff = 0x1p-10;
constexpr double kHalfSubnormalStep = 0x1p-24;

// ldr8: x = exp2(-c) stored as round(255 x) / 255, within half a step of x;
// allowing a full step (1 / 255) covers round-toward-zero conversions too.
// The decode -log2(x) turns dx into dc = dx / (x ln 2).
constexpr double kLdr8Step = 1.0 / 255.0;
constexpr double kLdr8Saturation = 7.994353436858858;  // log2(255): the decode of x = 0
// float32 slack on exp2 / log2 in the shaders and on the decode's 1/255.
constexpr double kLdr8Slack = 1e-4;

std::string cameraJson(const std::string& projection) {
  if (projection == "orthographic")
    return R"("camera": {"position": [0, 10, 0], "target": [0, 0, 0], "up": [0, 0, -1],
               "projection": "orthographic", "height": 10, "near": 0.1, "far": 100})";
  // The far plane 1 below the floor: the point light's volume (range 3 from
  // 1.2 above the floor) reaches past it, and its back faces there must
  // still draw (depth clamp), or the floor under the light goes dark.
  if (projection == "orthographic-far-11")
    return R"("camera": {"position": [0, 10, 0], "target": [0, 0, 0], "up": [0, 0, -1],
               "projection": "orthographic", "height": 10, "near": 0.1, "far": 11})";
  // 0.5 above the floor, under the light, looking straight down.
  return R"("camera": {"position": [0.2, 0.5, 0.1], "target": [0.2, 0, 0.1], "up": [0, 0, -1],
               "projection": "perspective", "fov_y_deg": 60, "near": 0.1, "far": 100})";
}

// One 10 x 10 floor, albedo `albedo`, under `lights`, drawn on `path` with `buffer`.
std::string sceneJson(const std::string& camera, const std::string& albedo, const std::string& lights,
                      const std::string& path, const std::string& buffer) {
  return R"({
  "lightcts": 1, "name": "deferred-backend",
  "image": {"width": )" + std::to_string(kImageSize) + R"(, "height": )" + std::to_string(kImageSize) + R"(},
  )" + cameraJson(camera) + R"(,
  "pipeline": {"path": ")" + path + R"(", "deferred_buffer": ")" + buffer + R"("},
  "objects": [{"name": "floor", "mesh": {"type": "plane", "size": [10, 10], "subdivisions": 4},
               "material": {"albedo": )" + albedo + R"(}}],
  "lights": [)" + lights + R"(]
})";
}

// A point light whose range reaches part of the floor only (the disc of
// radius sqrt(3^2 - 1.2^2) = 2.75 around (1, 0, -0.5)), and a slanted
// directional light; coloured so the channels differ.
const std::string kPointAndDirectional = R"(
  {"name": "point", "type": "point", "position": [1, 1.2, -0.5], "range": 3, "color": [1, 0.6, 0.3], "intensity": 4},
  {"name": "sun", "type": "directional", "direction": [0.3, -1, 0.2], "color": [0.2, 0.5, 1], "intensity": 0.7})";

// The camera 0.5 above the floor is inside this light's range (1.5 away, range 4).
const std::string kPointAroundCamera = R"(
  {"name": "point", "type": "point", "position": [0, 2, 0], "range": 4, "color": [1, 0.8, 0.6], "intensity": 3})";

lighting::Frame frameOf(const std::string& json) {
  return lighting::prepareFrame(lighting::prepareScene(scene_input::loadSceneText(json, "deferred-backend.json")), 0);
}

struct Allowed {
  double relative = 0;
  double absolute = 0;
};

// Every pixel's RGB within `allowed(value)` of `expected`'s, A = 1; returns
// the largest |difference|.
double compareImages(const std::string& what, const imaging::Image& rendered, const imaging::Image& expected,
                     const std::function<double(double expectedValue)>& allowed) {
  EXPECT_EQ(rendered.width, expected.width) << what;
  EXPECT_EQ(rendered.height, expected.height) << what;
  if (rendered.width != expected.width || rendered.height != expected.height) return INFINITY;
  int failures = 0;
  double largest = 0;
  for (int j = 0; j < rendered.height; ++j)
    for (int i = 0; i < rendered.width; ++i) {
      for (int c = 0; c < 3; ++c) {
        const double e = expected.at(i, j, c);
        const double r = rendered.at(i, j, c);
        const double difference = std::abs(r - e);
        largest = std::max(largest, difference);
        if (!(difference <= allowed(e)) && ++failures <= kReportedFailures)
          ADD_FAILURE() << what << ": pixel (" << i << ", " << j << ") channel " << c << ": " << r << ", forward "
                        << e << ", difference " << difference << " (allowed " << allowed(e) << ")";
      }
      if (rendered.at(i, j, 3) != 1.0f && ++failures <= kReportedFailures)
        ADD_FAILURE() << what << ": pixel (" << i << ", " << j << ") A = " << rendered.at(i, j, 3);
    }
  EXPECT_EQ(failures, 0) << what << ": failing channels (first " << kReportedFailures << " shown)";
  std::printf("[ %s ] largest difference: %.3g\n", what.c_str(), largest);
  return largest;
}

// The share of RGB channels of `image` that are above `threshold`.
double litShare(const imaging::Image& image, double threshold) {
  long lit = 0;
  for (int j = 0; j < image.height; ++j)
    for (int i = 0; i < image.width; ++i)
      for (int c = 0; c < 3; ++c) lit += image.at(i, j, c) > threshold;
  return double(lit) / (3.0 * image.width * image.height);
}

class Deferred : public ::testing::TestWithParam<Combination> {
 protected:
  // The backend, or null after GTEST_SKIP (check with IsSkipped()).
  std::unique_ptr<backends::Backend> backend(shaders::Mutant mutant = shaders::Mutant::None) {
    const Combination& c = GetParam();
    const backends::BackendEntry* entry = backends::findBuiltBackendEntry(c.backend);
    if (!entry) {
      whyNot_ = c.backend + " is not built";
      return nullptr;
    }
    backends::BackendOptions options;
    options.driver = c.driver;
    options.validation = true;
    options.variant.mutant = mutant;
    try {
      return entry->create(options);
    } catch (const backends::NotSupportedError& e) {
      whyNot_ = c.suffix + ": " + e.what();
      return nullptr;
    }
  }

  // The render, or nothing with whyNot_ set when the backend reports the
  // deferred path (or this buffer format) as not supported here: a skip.
  std::optional<imaging::Image> render(backends::Backend& b, const std::string& json) {
    try {
      return b.render(frameOf(json));
    } catch (const backends::NotSupportedError& e) {
      whyNot_ = GetParam().suffix + ": " + e.what();
      return std::nullopt;
    }
  }

  std::string whyNot_;
};

TEST_P(Deferred, Hdr32MatchesForward) {
  const auto b = backend();
  if (!b) GTEST_SKIP() << whyNot_;
  const auto forward = render(*b, sceneJson("orthographic", "[0.9, 0.8, 0.7]", kPointAndDirectional, "forward", "hdr32"));
  ASSERT_TRUE(forward);
  const auto deferred = render(*b, sceneJson("orthographic", "[0.9, 0.8, 0.7]", kPointAndDirectional, "deferred", "hdr32"));
  if (!deferred) GTEST_SKIP() << whyNot_;
  // The point light reaches part of the image only: both sides of its edge are compared.
  ASSERT_GT(litShare(*forward, 0.2), 0.05);
  compareImages(GetParam().suffix + " hdr32", *deferred, *forward,
                [](double e) { return kHdr32Relative * std::abs(e) + kHdr32Absolute; });
}

TEST_P(Deferred, Hdr32MatchesForwardWithVolumesPastTheFarPlane) {
  const auto b = backend();
  if (!b) GTEST_SKIP() << whyNot_;
  const std::string camera = "orthographic-far-11";
  const auto forward = render(*b, sceneJson(camera, "[0.9, 0.8, 0.7]", kPointAndDirectional, "forward", "hdr32"));
  ASSERT_TRUE(forward);
  const auto deferred = render(*b, sceneJson(camera, "[0.9, 0.8, 0.7]", kPointAndDirectional, "deferred", "hdr32"));
  if (!deferred) GTEST_SKIP() << whyNot_;
  compareImages(GetParam().suffix + " hdr32 far plane", *deferred, *forward,
                [](double e) { return kHdr32Relative * std::abs(e) + kHdr32Absolute; });
}

TEST_P(Deferred, Hdr16IsForwardRoundedToHalfPerLight) {
  const auto b = backend();
  if (!b) GTEST_SKIP() << whyNot_;
  const auto forward = render(*b, sceneJson("orthographic", "[0.9, 0.8, 0.7]", kPointAndDirectional, "forward", "hdr32"));
  ASSERT_TRUE(forward);
  const auto deferred = render(*b, sceneJson("orthographic", "[0.9, 0.8, 0.7]", kPointAndDirectional, "deferred", "hdr16"));
  if (!deferred) GTEST_SKIP() << whyNot_;
  constexpr int kLights = 2;
  const double largest = compareImages(GetParam().suffix + " hdr16", *deferred, *forward, [](double e) {
    return kLights * 2 * (kHalfUnitRoundoff * std::abs(e) + kHalfSubnormalStep) + kHdr32Relative * std::abs(e) +
           kHdr32Absolute;
  });
  // Half precision is really in use: hdr32's bound alone would not hold
  // everywhere (values near 1 lose ~2^-12 in half).
  EXPECT_GT(largest, 1e-5) << "the hdr16 light buffer looks like 32-bit floats";
}

// One directional light straight down on an albedo-1 floor: c = intensity
// everywhere, so every pixel decodes to the same value.
void checkLdr8(const std::string& what, const imaging::Image& image, double expected, double allowed) {
  imaging::Image uniform(image.width, image.height, 4);
  for (int j = 0; j < image.height; ++j)
    for (int i = 0; i < image.width; ++i) {
      for (int c = 0; c < 3; ++c) uniform.at(i, j, c) = float(expected);
      uniform.at(i, j, 3) = 1.0f;
    }
  compareImages(what, image, uniform, [&](double) { return allowed; });
}

std::string sunStraightDown(double intensity) {
  return R"({"name": "sun", "type": "directional", "direction": [0, -1, 0], "color": [1, 1, 1], "intensity": )" +
         std::to_string(intensity) + "}";
}

TEST_P(Deferred, Ldr8DecodesTheLightSumWithin8BitsAndSaturates) {
  const auto b = backend();
  if (!b) GTEST_SKIP() << whyNot_;
  // c = 1: x = 0.5, dc <= (1/255) / (0.5 ln 2) = 0.0113.
  const auto one = render(*b, sceneJson("orthographic", "[1, 1, 1]", sunStraightDown(1.0), "deferred", "ldr8"));
  if (!one) GTEST_SKIP() << whyNot_;
  checkLdr8(GetParam().suffix + " ldr8 sum 1", *one, 1.0, kLdr8Step / (0.5 * std::log(2.0)) + kLdr8Slack);
  // c = 20: x = 2^-20 stores as 0, which decodes to log2(255).
  const auto twenty = render(*b, sceneJson("orthographic", "[1, 1, 1]", sunStraightDown(20.0), "deferred", "ldr8"));
  ASSERT_TRUE(twenty);
  checkLdr8(GetParam().suffix + " ldr8 sum 20", *twenty, kLdr8Saturation, kLdr8Slack);
}

TEST_P(Deferred, CameraInsideAPointLightsVolumeMatchesForward) {
  const auto b = backend();
  if (!b) GTEST_SKIP() << whyNot_;
  const auto forward = render(*b, sceneJson("perspective", "[1, 0.9, 0.8]", kPointAroundCamera, "forward", "hdr32"));
  ASSERT_TRUE(forward);
  const auto deferred = render(*b, sceneJson("perspective", "[1, 0.9, 0.8]", kPointAroundCamera, "deferred", "hdr32"));
  if (!deferred) GTEST_SKIP() << whyNot_;
  ASSERT_GT(litShare(*forward, 0.1), 0.99) << "the whole view should be lit";
  compareImages(GetParam().suffix + " camera inside", *deferred, *forward,
                [](double e) { return kHdr32Relative * std::abs(e) + kHdr32Absolute; });
}

// What the mutant breaks: the volume around the camera is drawn front faces
// with LESS_OR_EQUAL, its front faces are behind the camera, and the floor
// stays dark where forward lights all of it.
TEST_P(Deferred, PointVolumeOutsideOnlyMutantLeavesTheCameraInsideDark) {
  const auto b = backend(shaders::Mutant::PointVolumeOutsideOnly);
  if (!b) GTEST_SKIP() << whyNot_;
  const auto forward = render(*b, sceneJson("perspective", "[1, 0.9, 0.8]", kPointAroundCamera, "forward", "hdr32"));
  ASSERT_TRUE(forward);
  const auto deferred = render(*b, sceneJson("perspective", "[1, 0.9, 0.8]", kPointAroundCamera, "deferred", "hdr32"));
  if (!deferred) GTEST_SKIP() << whyNot_;
  ASSERT_GT(litShare(*forward, 0.1), 0.99);
  EXPECT_LT(litShare(*deferred, 0.1), 0.01) << "the mutant's volume still lit the floor";
}

// One backend drawing hdr32, then ldr8 (new light buffer format, new
// targets), then hdr32 again gives the first image again, bit for bit; and
// the device time, where the backend measures one, covers the deferred draw.
TEST_P(Deferred, SwitchingLightBuffersLeavesNothingStale) {
  const auto b = backend();
  if (!b) GTEST_SKIP() << whyNot_;
  const std::string hdr32 = sceneJson("orthographic", "[0.9, 0.8, 0.7]", kPointAndDirectional, "deferred", "hdr32");
  const auto first = render(*b, hdr32);
  if (!first) GTEST_SKIP() << whyNot_;
  if (const std::optional<double> ms = b->lastDrawDeviceMilliseconds()) {
    EXPECT_GT(*ms, 0.0);
  }
  ASSERT_TRUE(render(*b, sceneJson("orthographic", "[1, 1, 1]", sunStraightDown(1.0), "deferred", "ldr8")));
  const auto again = render(*b, hdr32);
  ASSERT_TRUE(again);
  compareImages(GetParam().suffix + " hdr32 again", *again, *first, [](double) { return 0.0; });
}

INSTANTIATE_TEST_SUITE_P(EveryCombination, Deferred, ::testing::ValuesIn(backends::testing::allCombinations()),
                         backends::testing::combinationTestName);

}  // namespace
