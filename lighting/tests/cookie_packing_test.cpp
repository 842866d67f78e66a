// The cookie block (lighting/cookie_packing.h) against SPEC 3.10's
// coordinates in double (lighting/cookie.h): the float32 map applied to a
// camera-relative position gives the same cookie coordinates, also 1e5 m
// from the origin, and the slots follow the kept lights.
#include "lighting/cookie.h"
#include "lighting/cookie_packing.h"
#include "lighting/deferred_lights.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <memory>

namespace lighting {
namespace {

Cookie cookieOf(int faces) {
  Cookie c;
  auto image = std::make_shared<CookieImage>();
  image->width = image->height = 2;
  image->texels = {0.1f, 0.2f, 0.3f, 0.4f};
  for (int f = 0; f < faces; ++f) c.images.push_back(image);
  c.sizeX = 1.7;
  c.sizeY = 0.9;
  return c;
}

Scene farScene() {
  Scene s;
  const Vec3 far(1e5, 0, -1e5);
  s.camera.position = far + Vec3(0, 10, 0);
  s.camera.target = far;
  Light d;
  d.type = LightType::Directional;
  d.direction = glm::normalize(Vec3(0.3, -1, 0.2));
  d.cookie = cookieOf(1);
  Light spot;
  spot.type = LightType::Spot;
  spot.position = far + Vec3(0.5, 3, -0.4);
  spot.direction = glm::normalize(Vec3(0.1, -1, 0.3));
  spot.spotAngleDeg = 70;
  spot.cookie = cookieOf(1);
  Light point;
  point.type = LightType::Point;
  point.position = far + Vec3(-1, 1, 0.5);
  point.range = 6;
  point.cookie = cookieOf(6);
  s.lights = {d, spot, point};
  return s;
}

glm::dvec4 apply(const GpuMat4& m, const glm::vec3& p) {
  glm::dvec4 out(0.0);
  for (int r = 0; r < 4; ++r)
    out[r] = double(m.m[r]) * p.x + double(m.m[4 + r]) * p.y + double(m.m[8 + r]) * p.z + double(m.m[12 + r]);
  return out;
}

TEST(CookiePacking, TheFloatMapGivesSpec310sCoordinatesFarFromTheOrigin) {
  const Frame frame = prepareFrame(prepareScene(farScene()), 0);
  ASSERT_EQ(frame.cookies.textureLights.size(), 2u);
  ASSERT_EQ(frame.cookies.cubeLights.size(), 1u);
  EXPECT_TRUE(frame.features.cookies);
  const GpuCookieBlock block = packCookieBlock(frame);
  const Scene& s = frame.scene();
  const Vec3 camera = frame.view.camera.position;
  for (const Vec3& offset : {Vec3(0.3, 0, 0.2), Vec3(-2.1, 0, 1.4), Vec3(1.9, 0, -2.6)}) {
    const Vec3 p = Vec3(1e5, 0, -1e5) + offset;
    const glm::vec3 rel(p - camera);  // what the shader sees, in float
    // Directional: u, v up to an integer (the sampler repeats).
    const CookieCoordinates d = cookieCoordinates(s.lights[0], p);
    const glm::dvec4 du = apply(block.cookies[cookieBlockSlot(frame, 0)].toCookie, rel);
    EXPECT_NEAR(std::remainder(du.x - d.u, 1.0), 0.0, 1e-6);
    EXPECT_NEAR(std::remainder(du.y - d.v, 1.0), 0.0, 1e-6);
    // Spot: uv = 0.5 + scale q.xy / q.z.
    const GpuCookie& sc = block.cookies[cookieBlockSlot(frame, 1)];
    const CookieCoordinates sp = cookieCoordinates(s.lights[1], p);
    const glm::dvec4 q = apply(sc.toCookie, rel);
    EXPECT_EQ(sc.params.x, float(int(GpuCookieKind::Spot)));
    EXPECT_NEAR(0.5 + sc.params.y * q.x / q.z, sp.u, 1e-6);
    EXPECT_NEAR(0.5 + sc.params.y * q.y / q.z, sp.v, 1e-6);
    // Point: the direction selects the same face and (u, v).
    const int cubeSlot = cookieBlockSlot(frame, 2);
    EXPECT_EQ(cubeSlot, kMaxCookieTextures);
    const glm::dvec4 dir = apply(block.cookies[cubeSlot].toCookie, rel);
    const CookieCoordinates want = cookieCoordinates(s.lights[2], p), got = cubeCoordinates(Vec3(dir));
    EXPECT_EQ(got.face, want.face);
    EXPECT_NEAR(got.u, want.u, 1e-6);
    EXPECT_NEAR(got.v, want.v, 1e-6);
  }
}

TEST(CookiePacking, OnlyKeptLightsTakeSlotsAndTooManyIsSaid) {
  Scene s = farScene();
  s.lights.resize(1);  // the directional light
  for (int k = 0; k < 5; ++k) {
    Light spot = farScene().lights[1];
    spot.name = "spot" + std::to_string(k);
    s.lights.push_back(spot);
  }
  const Frame frame = prepareFrame(prepareScene(s), 0);
  EXPECT_EQ(int(frame.cookies.textureLights.size()), kMaxCookieTextures);
  EXPECT_NE(frame.cookies.overflow.find("more than 4 2D cookies"), std::string::npos) << frame.cookies.overflow;
  Scene plain = farScene();
  for (Light& l : plain.lights) l.cookie.reset();
  const Frame none = prepareFrame(prepareScene(plain), 0);
  EXPECT_FALSE(none.cookies.any());
  EXPECT_FALSE(none.features.cookies);
  EXPECT_EQ(cookieBlockSlot(none, 0), -1);
}

// A deferred light pass draw looks up its light's cookie slot alone: the
// 2D slots are 0-3 and the cube slots 4-5 (shaders/cookies.glsl), so the
// directional and spot cookies hold 0 and 1 between them and the point
// light's cube the first cube slot, 4; no light here has a shadow map.
TEST(CookiePacking, EachLightPassLooksUpItsOwnSlot) {
  const Frame frame = prepareFrame(prepareScene(farScene()), 0);
  const std::vector<LightVolume> volumes = lightVolumes(frame);
  ASSERT_EQ(volumes.size(), 3u);
  std::vector<int> textureSlots;
  for (const LightVolume& v : volumes) {
    EXPECT_EQ(v.slots.shadow, -1);
    if (v.light == 2) EXPECT_EQ(v.slots.cookie, 4);
    else textureSlots.push_back(v.slots.cookie);
  }
  std::sort(textureSlots.begin(), textureSlots.end());
  EXPECT_EQ(textureSlots, (std::vector<int>{0, 1}));
}

}  // namespace
}  // namespace lighting
