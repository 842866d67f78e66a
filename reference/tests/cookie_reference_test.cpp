// SPEC 3.10 in the reference: a light's cookie multiplies its term, and the
// tolerance grows by the lookup's bound (reference/cookie_bound.cpp).
#include "lighting/camera_view.h"
#include "lighting/cookie.h"
#include "reference/cookie_bound.h"
#include "reference/reference_renderer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

namespace reference {
namespace {

using namespace lighting;

std::shared_ptr<const CookieImage> checker(int n, float dark, float light) {
  auto c = std::make_shared<CookieImage>();
  c->width = c->height = n;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) c->texels.push_back((i + j) % 2 ? light : dark);
  return c;
}

Scene spotScene(bool withCookie) {
  Scene s;
  s.image = {32, 32};
  Object floor;
  floor.mesh.planeSizeX = floor.mesh.planeSizeZ = 10;
  floor.albedo = {0.6, 0.5, 0.4};
  s.objects.push_back(floor);
  Light spot;
  spot.type = LightType::Spot;
  spot.position = {0.3, 2, -0.2};
  spot.direction = {0, -1, 0};
  spot.spotAngleDeg = 90;
  spot.innerSpotAngleDeg = 80;
  spot.range = 8;
  if (withCookie) {
    Cookie cookie;
    cookie.images.push_back(checker(4, 0.25f, 0.75f));
    spot.cookie = cookie;
  }
  s.lights.push_back(spot);
  return s;
}

ReferenceImages renderCookieScene(const Scene& s) {
  auto prepared = prepareScene(s);
  ReferenceOptions options;
  options.keepExactValues = true;
  return ReferenceRenderer(prepared).render(prepareFrame(prepared, 0), options);
}

TEST(CookieReference, TheCookieMultipliesTheLightsTermAndWidensTheTolerance) {
  const Scene with = spotScene(true);
  const ReferenceImages a = renderCookieScene(with), b = renderCookieScene(spotScene(false));
  const Light& light = with.lights[0];
  const CameraView view = cameraViewForFrame(with, 0);
  int checked = 0, widened = 0;
  for (int j = 0; j < 32; ++j)
    for (int i = 0; i < 32; ++i) {
      const std::size_t k = std::size_t(j) * 32 + i;
      if (b.exactValue[k].r == 0) continue;
      // The floor is y = 0: the pixel centre's ray meets it here.
      const Ray ray = view.rayThroughPixel(i + 0.5, j + 0.5);
      const Vec3 p = ray.origin + ray.direction * (-ray.origin.y / ray.direction.y);
      const double cookie = cookieValue(light, p);
      EXPECT_NEAR(a.exactValue[k].r, b.exactValue[k].r * cookie, 1e-12 * b.exactValue[k].r);
      widened += a.tolerance.at(i, j, 0) > cookie * b.tolerance.at(i, j, 0) ? 1 : 0;
      ++checked;
    }
  EXPECT_GT(checked, 100);  // the cone covers a disc of radius 2 of the 10 x 10 view
  EXPECT_GT(widened, checked / 2) << "the lookup's bound adds to most pixels' tolerance";
}

TEST(CookieReference, BoundCoversEitherFaceAtACubeEdge) {
  Light l;
  l.type = LightType::Point;
  Cookie cookie;
  for (int f = 0; f < 6; ++f) cookie.images.push_back(checker(2, 0.1f * float(f), 0.1f * float(f) + 0.05f));
  l.cookie = cookie;
  // Exactly on the +X / +Z edge, a position error of 1e-3 reaches both faces.
  const CookieBound b = cookieWithBound(l, glm::normalize(Vec3(1, 0.2, 1)), 1e-3);
  const double onX = cookieValue(l, glm::normalize(Vec3(1, 0.2, 1 - 1e-3)));
  const double onZ = cookieValue(l, glm::normalize(Vec3(1 - 1e-3, 0.2, 1)));
  EXPECT_LE(std::abs(onX - b.value), b.errorBound);
  EXPECT_LE(std::abs(onZ - b.value), b.errorBound);
}

// SPEC 7: a device that reports 8 sub-texel bits has its weights' term cut
// from 2 x 2^-4 to 2 x 2^-8 of the taps' spread, and nothing else changes.
TEST(CookieReference, FilterTermFollowsTheWeightPrecision) {
  Light l;
  l.type = LightType::Spot;
  l.position = {0, 0, 0};
  l.direction = {0, 0, 1};
  l.spotAngleDeg = 90;
  Cookie cookie;
  cookie.images.push_back(checker(4, 0.25f, 0.75f));  // every bilinear footprint spreads 0.5
  l.cookie = cookie;
  const Vec3 p(0.1, 0.05, 1.0);
  const CookieBound coarse = cookieWithBound(l, p, 0.0, 0x1p-4);
  const CookieBound fine = cookieWithBound(l, p, 0.0, 0x1p-8);
  EXPECT_EQ(coarse.value, fine.value);
  EXPECT_NEAR(coarse.errorBound - fine.errorBound, 2 * (0x1p-4 - 0x1p-8) * 0.5, 1e-15);
}

}  // namespace
}  // namespace reference
