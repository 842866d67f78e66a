// Light cookies (SPEC 3.10) on every combination, against a hand derivation:
// a cookie of one texel of value 0.5 is 0.5 wherever it is sampled (any
// filter weights sum to 1; repeat, clamp and the cube's faces all read that
// texel), so it must halve the light's contribution and change nothing else:
// the cookie's image is exactly half the cookie-free one, up to the filter's
// blend rounding. More cookies than slots is NotSupported
// (backends/drawable_features.h), never drawn without them.
#include "backends/tests/backend_combinations.h"
#include "lighting/frame.h"

#include <cmath>
#include <memory>

namespace {

using namespace lighting;

// A blend of four weights summing to 1 of one value v, in float32: v times
// (w0 + w1 + w2 + w3) with each product and sum rounded, within 8 units of
// roundoff of v (7 roundings, and the weights' own sum exact in the filter's
// fixed point). The rest of the lighting is scaled by exactly 0.5.
constexpr double kHalfCookieRelativeError = 8 * 0x1p-24;

Cookie constantCookie(int faces) {
  Cookie cookie;
  auto image = std::make_shared<CookieImage>();
  image->width = image->height = 1;
  image->texels = {0.5f};
  for (int f = 0; f < faces; ++f) cookie.images.push_back(image);
  return cookie;
}

Scene oneLightScene(LightType type, bool withCookie) {
  Scene s;
  s.image = {16, 16};
  s.camera.position = {0, 6, 6};
  s.camera.target = {0, 0, 0};
  Object floor;
  floor.mesh.planeSizeX = floor.mesh.planeSizeZ = 10;
  s.objects.push_back(floor);
  Light light;
  light.name = "cookied";
  light.type = type;
  light.position = {0.5, 1.5, 0.3};
  light.direction = glm::normalize(Vec3(0.2, -1, 0.1));
  light.range = 6;
  light.spotAngleDeg = 120;
  if (withCookie) light.cookie = constantCookie(type == LightType::Point ? 6 : 1);
  s.lights.push_back(light);
  return s;
}

class CookieOnBackend : public ::testing::TestWithParam<backends::testing::Combination> {};

TEST_P(CookieOnBackend, AHalfCookieHalvesTheLightOfEveryKind) {
  std::string whyNot;
  const std::unique_ptr<backends::Backend> backend = backends::testing::createOrNull(GetParam(), whyNot);
  if (!backend) GTEST_SKIP() << whyNot;
  for (LightType type : {LightType::Directional, LightType::Spot, LightType::Point}) {
    SCOPED_TRACE(type == LightType::Directional ? "directional" : type == LightType::Spot ? "spot" : "point");
    const Frame plain = prepareFrame(prepareScene(oneLightScene(type, false)), 0);
    const Frame cookied = prepareFrame(prepareScene(oneLightScene(type, true)), 0);
    ASSERT_TRUE(cookied.features.cookies);
    const imaging::Image a = backend->render(plain);
    const imaging::Image b = backend->render(cookied);
    int lit = 0;
    for (int y = 0; y < a.height; ++y)
      for (int x = 0; x < a.width; ++x)
        for (int c = 0; c < 3; ++c) {
          const double expected = 0.5 * a.at(x, y, c);
          lit += expected > 0 ? 1 : 0;
          EXPECT_NEAR(b.at(x, y, c), expected, kHalfCookieRelativeError * expected) << x << ", " << y << " " << c;
        }
    EXPECT_GT(lit, 30);  // the light reaches the floor in the image
  }
}

TEST_P(CookieOnBackend, MoreCookiesThanSlotsIsNotSupported) {
  std::string whyNot;
  const std::unique_ptr<backends::Backend> backend = backends::testing::createOrNull(GetParam(), whyNot);
  if (!backend) GTEST_SKIP() << whyNot;
  Scene s = oneLightScene(LightType::Spot, true);
  for (int k = 0; k < kMaxCookieTextures; ++k) {
    s.lights.push_back(s.lights.front());
    s.lights.back().name = "spot " + std::to_string(k);
  }
  const Frame frame = prepareFrame(prepareScene(s), 0);
  ASSERT_FALSE(frame.cookies.overflow.empty());
  EXPECT_THROW(backend->preparePipeline(frame), backends::NotSupportedError);
  EXPECT_THROW(backend->draw(frame), backends::NotSupportedError);
}

INSTANTIATE_TEST_SUITE_P(EveryBackend, CookieOnBackend, ::testing::ValuesIn(backends::testing::allCombinations()),
                         backends::testing::combinationTestName);

}  // namespace
