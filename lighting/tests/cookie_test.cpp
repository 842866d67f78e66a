// SPEC 3.10's lookup in double (lighting/cookie.cpp): properties a correct
// lookup must have, apart from the independent evaluation of
// cookie_independent_test.cpp.
#include "lighting/cookie.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <memory>

namespace lighting {
namespace {

std::shared_ptr<const CookieImage> image(int w, int h, double base) {
  auto c = std::make_shared<CookieImage>();
  c->width = w;
  c->height = h;
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) c->texels.push_back(float(base + 0.01 * i + 0.1 * j));
  return c;
}

Light cubeLight() {
  Light l;
  l.type = LightType::Point;
  l.position = {0.3, -0.2, 0.1};
  Cookie cookie;
  for (int f = 0; f < 6; ++f) cookie.images.push_back(image(4, 4, 0.1 * f));
  l.cookie = cookie;
  return l;
}

TEST(Cookie, LightBasisIsOrthonormalAndSwitchesUpNearVertical) {
  for (const Vec3& d : {Vec3(0.3, -1, 0.2), Vec3(0, -1, 0), Vec3(1, 0, 0), Vec3(0.001, 1, 0)}) {
    const LightBasis b = lightBasis(d);
    EXPECT_NEAR(glm::length(b.r), 1, 1e-15);
    EXPECT_NEAR(glm::length(b.u), 1, 1e-15);
    EXPECT_NEAR(glm::dot(b.r, b.f), 0, 1e-15);
    EXPECT_NEAR(glm::dot(b.u, b.f), 0, 1e-15);
    EXPECT_NEAR(glm::dot(b.r, b.u), 0, 1e-15);
  }
  EXPECT_EQ(lightBasis(Vec3(0, -1, 0)).r, Vec3(-1, 0, 0));  // up = +Z: cross((0,-1,0), (0,0,1))
}

TEST(Cookie, DirectionalCookieRepeatsEveryTile) {
  Light l;
  l.type = LightType::Directional;
  l.direction = glm::normalize(Vec3(0.2, -1, 0.1));
  Cookie cookie;
  cookie.images.push_back(image(3, 2, 0.2));
  cookie.sizeX = 1.5;
  cookie.sizeY = 0.75;
  l.cookie = cookie;
  const LightBasis b = lightBasis(l.direction);
  const Vec3 p(0.37, 0.0, -0.21);
  const double v = cookieValue(l, p);
  for (int k : {1, 7, 1000})
    EXPECT_NEAR(cookieValue(l, p + double(k) * (1.5 * b.r + 0.75 * b.u)), v, 1e-9) << k << " tiles away";
}

TEST(Cookie, SpotCookieIsZeroBehindTheApexAndClampsOutsideTheCone) {
  Light l;
  l.type = LightType::Spot;
  l.position = {0, 2, 0};
  l.direction = {0, -1, 0};
  l.spotAngleDeg = 60;
  Cookie cookie;
  cookie.images.push_back(image(4, 4, 0.3));
  l.cookie = cookie;
  EXPECT_EQ(cookieValue(l, {0.1, 3, 0.2}), 0.0);   // q.z < 0: behind the light
  EXPECT_EQ(cookieValue(l, {0.5, 2, 0.0}), 0.0);   // q.z = 0
  const double edge = cookieValue(l, {50, 0, 0});  // far outside the cone: clamped to the edge texels
  EXPECT_NEAR(cookieValue(l, {80, 0, 0}), edge, 1e-12);
}

TEST(Cookie, CubeFacesAreChosenByTheMajorAxisAndFilterSeamlessly) {
  const Light l = cubeLight();
  // Face centres: the mean of the four central texels of each face.
  const Vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (int f = 0; f < 6; ++f) {
    EXPECT_EQ(cubeCoordinates(axes[f]).face, f);
    EXPECT_NEAR(cookieValue(l, l.position + axes[f]), 0.1 * f + 0.015 + 0.15, 1e-7) << "face " << f;
  }
  // Crossing an edge or a corner, the value is continuous: seamless filtering.
  for (const Vec3& edge : {Vec3(1, 0.3, 1), Vec3(1, 1, -0.2), Vec3(-1, -0.6, -1), Vec3(0.1, 1, -1), Vec3(1, 1, 1),
                           Vec3(-1, 1, -1)}) {
    const Vec3 a = glm::normalize(edge) + Vec3(1e-9, 0, 0), b = glm::normalize(edge) - Vec3(1e-9, 0, 0);
    const Vec3 c = glm::normalize(edge) + Vec3(0, 0, 1e-9), d = glm::normalize(edge) - Vec3(0, 1e-9, 0);
    const double v = cookieValue(l, l.position + a);
    EXPECT_NEAR(cookieValue(l, l.position + b), v, 1e-6) << edge.x << " " << edge.y << " " << edge.z;
    EXPECT_NEAR(cookieValue(l, l.position + c), v, 1e-6) << edge.x << " " << edge.y << " " << edge.z;
    EXPECT_NEAR(cookieValue(l, l.position + d), v, 1e-6) << edge.x << " " << edge.y << " " << edge.z;
  }
}

}  // namespace
}  // namespace lighting
