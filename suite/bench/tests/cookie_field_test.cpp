// The cookie modes of the benchmark field (SPEC 3.10 and 9, cookies on and
// off; docs/bench-format.md): `cookies` and `cookie-lights` are in every set
// the frame benchmarks run, the `cookies` frame really samples cookies
// within a frame's slots (no overflow, which the backends would report
// NotSupported), and `cookie-lights` is the same light set without any.
#include "lighting/cookie_slots.h"
#include "lighting/frame.h"
#include "suite/bench/bench_families.h"
#include "suite/bench/bench_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <optional>
#include <set>
#include <string>

namespace {

using namespace lighting;

std::optional<bench::FieldModeSpec> modeNamed(const std::string& name, bool quick, bool slow) {
  for (const bench::FieldModeSpec& mode : bench::fieldModeSpecs(quick, slow))
    if (mode.name == name) return mode;
  return std::nullopt;
}

Frame frameOf(const bench::FieldSpec& field) { return prepareFrame(prepareScene(bench::fieldScene(field, "test")), 0); }

TEST(CookieField, BothModesInTheFullSetNotInQuick) {
  for (const bool slow : {false, true}) {
    EXPECT_FALSE(modeNamed(bench::kCookiesMode, true, slow));
    EXPECT_FALSE(modeNamed(bench::kCookieLightsMode, true, slow));
  }
  for (const bool quick : {false}) {
    for (const bool slow : {false, true}) {
      SCOPED_TRACE(std::string(quick ? "quick" : "full") + (slow ? ", slow driver" : ""));
      const auto on = modeNamed(bench::kCookiesMode, quick, slow);
      const auto off = modeNamed(bench::kCookieLightsMode, quick, slow);
      ASSERT_TRUE(on && off);
      EXPECT_TRUE(on->field.cookies);
      EXPECT_FALSE(off->field.cookies);
      EXPECT_TRUE(off->field.cookieLights);
      for (const auto* mode : {&*on, &*off}) {
        EXPECT_EQ(mode->field.mode, bench::FrameMode::AllLights);
        EXPECT_FALSE(mode->fullShader);
        EXPECT_FALSE(mode->field.specularBrdf);
      }
    }
  }
}

TEST(CookieField, CookiesModeHasCookiesWithinTheSlots) {
  const Frame frame = frameOf(modeNamed(bench::kCookiesMode, false, false)->field);
  EXPECT_TRUE(frame.features.cookies);
  EXPECT_EQ(frame.cookies.overflow, "");
  EXPECT_TRUE(frame.cookies.any());
  EXPECT_EQ(frame.cookies.textureLights.size(), 3u);  // directional + 2 spots
  EXPECT_EQ(frame.cookies.cubeLights.size(), 2u);
  EXPECT_LE(int(frame.cookies.textureLights.size()), kMaxCookieTextures);
  EXPECT_LE(int(frame.cookies.cubeLights.size()), kMaxCookieCubes);
  EXPECT_TRUE(frame.features.directionalLights);
  EXPECT_TRUE(frame.features.spotLights);
  EXPECT_TRUE(frame.features.pointLights);
  // Every light in view and kept: 64 point/spot lights and the directional one.
  EXPECT_EQ(frame.selection.packed.other.size(), 64u);
  EXPECT_EQ(frame.selection.packed.directional.size(), 1u);
  const int size = modeNamed(bench::kCookiesMode, false, false)->field.cookieSize;
  int cookied = 0;
  for (const Light& l : frame.scene().lights) {
    if (!l.cookie) continue;
    ++cookied;
    ASSERT_EQ(l.cookie->images.size(), l.type == LightType::Point ? 6u : 1u) << l.name;
    for (const auto& image : l.cookie->images) {
      EXPECT_EQ(image->width, size);
      EXPECT_EQ(image->height, size);
      ASSERT_EQ(image->texels.size(), std::size_t(size) * std::size_t(size));
      float lo = 1, hi = 0;
      for (const float t : image->texels) lo = std::min(lo, t), hi = std::max(hi, t);
      EXPECT_GE(lo, 0.0f);
      EXPECT_LE(hi, 1.0f);
      EXPECT_GT(hi - lo, 0.3f) << l.name << ": a pattern, not a constant";
    }
    if (l.type == LightType::Spot) {
      EXPECT_LE(l.spotAngleDeg, 170);  // SPEC 2: a spot cookie's cone
    }
  }
  EXPECT_EQ(cookied, 5);
}

TEST(CookieField, CookieLightsModeIsTheSameLightsWithoutCookies) {
  const Frame on = frameOf(modeNamed(bench::kCookiesMode, false, false)->field);
  const Frame off = frameOf(modeNamed(bench::kCookieLightsMode, false, false)->field);
  EXPECT_FALSE(off.features.cookies);
  EXPECT_FALSE(off.cookies.any());
  EXPECT_EQ(off.cookies.overflow, "");
  const auto& a = on.scene().lights;
  const auto& b = off.scene().lights;
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t l = 0; l < a.size(); ++l) {
    SCOPED_TRACE(a[l].name);
    EXPECT_FALSE(b[l].cookie.has_value());
    EXPECT_EQ(a[l].name, b[l].name);
    EXPECT_EQ(a[l].type, b[l].type);
    EXPECT_EQ(a[l].position, b[l].position);
    EXPECT_EQ(a[l].direction, b[l].direction);
    EXPECT_EQ(a[l].range, b[l].range);
    EXPECT_EQ(a[l].spotAngleDeg, b[l].spotAngleDeg);
    EXPECT_EQ(a[l].innerSpotAngleDeg, b[l].innerSpotAngleDeg);
    EXPECT_EQ(a[l].finalColor(), b[l].finalColor());
  }
  EXPECT_EQ(on.scene().objects.size(), off.scene().objects.size());
  EXPECT_EQ(on.selection.packed.other, off.selection.packed.other);
  EXPECT_EQ(on.selection.packed.directional, off.selection.packed.directional);
}

// The other modes of the field draw no cookie (and the plain field is the grid alone).
TEST(CookieField, OtherModesHaveNone) {
  for (const bench::FieldModeSpec& mode : bench::fieldModeSpecs(false, false)) {
    if (mode.name == bench::kCookiesMode) continue;
    SCOPED_TRACE(mode.name);
    EXPECT_FALSE(frameOf(mode.field).features.cookies);
  }
  EXPECT_EQ(bench::fieldScene(bench::FieldSpec{}, "plain").lights.size(), 64u);
}

// The upload benchmark's cookie sizes all fit the slots too.
TEST(CookieField, UploadSizesFitTheSlots) {
  for (const bool quick : {false, true}) EXPECT_FALSE(bench::cookieUploadSizes(quick).empty());
  bench::FieldSpec field;
  field.cookies = true;
  field.cookieSize = bench::cookieUploadSizes(false).front();
  const Frame frame = frameOf(field);
  EXPECT_TRUE(frame.features.cookies);
  EXPECT_EQ(frame.cookies.overflow, "");
  EXPECT_EQ(frame.scene().lights.back().cookie->images.front()->width, field.cookieSize);
}

// The second context path to a driver (gl-osmesa) times the light paths only:
// no feature modes, no full shader.
TEST(FieldModes, SecondContextPathHasTheLightPathModesOnly) {
  std::set<std::string> names;
  for (const bench::FieldModeSpec& mode : bench::fieldModeSpecs(false, false, true)) names.insert(mode.name);
  EXPECT_EQ(names, (std::set<std::string>{"all-lights", "per-object", "clustered", "legacy-4+4", "deferred-hdr32", "deferred-hdr16",
                                          "deferred-ldr8"}));
}

}  // namespace
