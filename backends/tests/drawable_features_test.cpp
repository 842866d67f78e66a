// A frame with a light cookie (SPEC 3.10), which no backend draws yet
// (issue 18), is NotSupported on every combination, in preparePipeline and
// in draw, never drawn as if it had none; the same scene without the cookie
// draws. backends/drawable_features.h.
#include "backends/tests/backend_combinations.h"
#include "lighting/frame.h"

#include <memory>

namespace {

using namespace lighting;

Scene spotScene(bool withCookie) {
  Scene s;
  s.image = {8, 8};
  Object floor;
  floor.mesh.planeSizeX = floor.mesh.planeSizeZ = 10;
  s.objects.push_back(floor);
  Light spot;
  spot.name = "cookied";
  if (withCookie) {
    Cookie cookie;
    auto image = std::make_shared<CookieImage>();
    image->width = image->height = 1;
    image->texels = {0.5f};
    cookie.images.push_back(image);
    spot.cookie = cookie;
  }
  s.lights.push_back(spot);
  return s;
}

class DrawableFeatures : public ::testing::TestWithParam<backends::testing::Combination> {};

TEST_P(DrawableFeatures, ACookieFrameIsNotSupportedAndTheSameFrameWithoutOneDraws) {
  std::string whyNot;
  const std::unique_ptr<backends::Backend> backend = backends::testing::createOrNull(GetParam(), whyNot);
  if (!backend) GTEST_SKIP() << whyNot;
  const Frame with = prepareFrame(prepareScene(spotScene(true)), 0);
  ASSERT_TRUE(with.features.cookies);
  EXPECT_THROW(backend->preparePipeline(with), backends::NotSupportedError);
  try {
    backend->draw(with);
    ADD_FAILURE() << "drew a frame with a cookie";
  } catch (const backends::NotSupportedError& e) {
    EXPECT_NE(std::string(e.what()).find("'cookied' has a cookie"), std::string::npos) << e.what();
  }
  const imaging::Image image = backend->render(prepareFrame(prepareScene(spotScene(false)), 0));
  EXPECT_EQ(image.width, 8);
}

INSTANTIATE_TEST_SUITE_P(EveryBackend, DrawableFeatures, ::testing::ValuesIn(backends::testing::allCombinations()),
                         backends::testing::combinationTestName);

}  // namespace
