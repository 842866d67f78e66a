// The baker's acceptance check: "A baked inverse-squared point light on a plane
// matches an independent evaluation of SPEC 3.6 at texel centres to 1e-6
// relative." Everything below is written out again from the SPEC text (the
// rotation of SPEC 1, the plane UV of 3.6, the distance clamp and range term
// of 3.2); nothing calls lighting/light_math, lighting/transform or the
// baker's helpers.
#include "baking/tests/test_scenes.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>

namespace baking::testing {
namespace {

struct V3 {
  double x, y, z;
};
V3 operator+(V3 a, V3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
V3 operator-(V3 a, V3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
V3 operator*(double s, V3 a) { return {s * a.x, s * a.y, s * a.z}; }
double dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

using M3 = std::array<std::array<double, 3>, 3>;  // row-major
M3 multiply(const M3& a, const M3& b) {
  M3 c{};
  for (int r = 0; r < 3; ++r)
    for (int k = 0; k < 3; ++k)
      for (int q = 0; q < 3; ++q) c[r][k] += a[r][q] * b[q][k];
  return c;
}
V3 apply(const M3& m, V3 v) {
  return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z, m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
          m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
}

// SPEC 1: R = Ry(y) * Rx(x) * Rz(z), standard right-handed axis rotations.
M3 rotation(double xDeg, double yDeg, double zDeg) {
  const double k = std::numbers::pi / 180;
  const double cx = std::cos(xDeg * k), sx = std::sin(xDeg * k);
  const double cy = std::cos(yDeg * k), sy = std::sin(yDeg * k);
  const double cz = std::cos(zDeg * k), sz = std::sin(zDeg * k);
  const M3 rx = {{{1, 0, 0}, {0, cx, -sx}, {0, sx, cx}}};
  const M3 ry = {{{cy, 0, sy}, {0, 1, 0}, {-sy, 0, cy}}};
  const M3 rz = {{{cz, -sz, 0}, {sz, cz, 0}, {0, 0, 1}}};
  return multiply(multiply(ry, rx), rz);
}

struct PlaneSetup {
  double sizeX, sizeZ, scale;
  V3 translate, rotateDeg;
  int n;
};

// SPEC 3.6, independently: texel (i, j) sits at ((i + .5)/N, (j + .5)/N);
// u = x/sx + 0.5 gives x = (u - 0.5) sx (z likewise); world = R (scale x) + t;
// N = R (0, 1, 0). E = finalColor * saturate(N.L) * rangeAtt / distSqr with
// distSqr = max(|ray|^2, 1e-5), L = ray / sqrt(distSqr),
// rangeAtt = saturate(1 - (distSqr / max(r^2, 1e-5))^2)^2.
double expectedIrradiance(const PlaneSetup& p, const M3& r, int i, int j, V3 lightPos, double range,
                          double finalColor) {
  const double u = (i + 0.5) / p.n, v = (j + 0.5) / p.n;
  const V3 local = {(u - 0.5) * p.sizeX, 0, (v - 0.5) * p.sizeZ};
  const V3 q = apply(r, p.scale * local) + p.translate;
  const V3 normal = apply(r, {0, 1, 0});
  const V3 ray = lightPos - q;
  const double distSqr = std::max(dot(ray, ray), 1e-5);
  const V3 L = (1 / std::sqrt(distSqr)) * ray;
  const double invRangeSq = 1 / std::max(range * range, 1e-5);
  const double t = std::clamp(1 - std::pow(distSqr * invRangeSq, 2), 0.0, 1.0);
  return finalColor * std::clamp(dot(normal, L), 0.0, 1.0) * t * t / distSqr;
}

TEST(IndependentPlaneBake, InverseSquaredPointMatchesSpecAtEveryTexelCentre) {
  const PlaneSetup p{6, 4, 1.5, {1.5, -2, 3}, {30, 45, 10}, 32};
  const M3 r = rotation(p.rotateDeg.x, p.rotateDeg.y, p.rotateDeg.z);
  const V3 centre = p.translate, normal = apply(r, {0, 1, 0}), side = apply(r, {1, 0, 0});

  Object plane = lightmappedPlane(p.sizeX, p.sizeZ, p.n);
  plane.transform.translate = {p.translate.x, p.translate.y, p.translate.z};
  plane.transform.rotateDeg = {p.rotateDeg.x, p.rotateDeg.y, p.rotateDeg.z};
  plane.transform.scale = p.scale;

  // Heights above the plane, the light off its centre so texels see a
  // spread of angles; the range cuts some texels off at the lowest height.
  for (const double height : {0.3, 1.0, 3.0}) {
    SCOPED_TRACE("height " + std::to_string(height));
    const V3 lightPos = centre + height * normal + 1.2 * side;
    const double range = 5, intensity = 2.5;
    Scene s;
    s.objects.push_back(plane);
    s.lights.push_back(pointLight({lightPos.x, lightPos.y, lightPos.z}, range, intensity, LightMode::Baked));
    const auto baked = bakeUncached(s);
    const lighting::TexelMap& map = baked->objects[0].lightmap;
    ASSERT_EQ(map.resolution, p.n);
    int lit = 0, worst = 0;
    for (int j = 0; j < p.n; ++j)
      for (int i = 0; i < p.n; ++i) {
        const double expected = expectedIrradiance(p, r, i, j, lightPos, range, intensity);
        const double actual = texel(map, i, j, 0);
        if (expected > 0) ++lit;
        if (std::abs(actual - expected) > 1e-6 * std::abs(expected)) {
          if (++worst <= 5) ADD_FAILURE() << "texel (" << i << ", " << j << "): " << actual << " vs " << expected;
        }
        EXPECT_EQ(texel(map, i, j, 1), texel(map, i, j, 0));  // white light
      }
    EXPECT_EQ(worst, 0);
    EXPECT_GT(lit, p.n * p.n / 4);  // the check covers lit texels, not only zeros
  }
}

}  // namespace
}  // namespace baking::testing
