#include "lighting/cookie.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lighting {
namespace {

// One face of the cube: the major axis and its sign, and the world axes (with
// signs) that sc and tc read, as in Vulkan's "Cube Map Face Selection" table.
struct FaceAxes {
  int major;
  double sign;
  int sAxis;
  double sSign;
  int tAxis;
  double tSign;
};
constexpr FaceAxes kFaces[6] = {
    {0, +1, 2, -1, 1, -1},  // +X: sc = -z, tc = -y
    {0, -1, 2, +1, 1, -1},  // -X: sc = +z, tc = -y
    {1, +1, 0, +1, 2, +1},  // +Y: sc = +x, tc = +z
    {1, -1, 0, +1, 2, -1},  // -Y: sc = +x, tc = -z
    {2, +1, 0, +1, 1, -1},  // +Z: sc = +x, tc = -y
    {2, -1, 0, -1, 1, -1},  // -Z: sc = -x, tc = -y
};

int wrap(int i, int n) { return ((i % n) + n) % n; }

// The point on face `face` of the cube [-1, 1]^3 at texel-centre coordinates
// (s, t) in [-1, 1].
Vec3 facePoint(int face, double s, double t) {
  const FaceAxes& a = kFaces[face];
  Vec3 d(0.0);
  d[a.major] = a.sign;
  d[a.sAxis] = a.sSign * s;
  d[a.tAxis] = a.tSign * t;
  return d;
}

// Texel (i, j) of an N x N face, with i or j possibly one texel outside it:
// the texel of the adjacent face across the edge (Vulkan's cube map edge
// handling). The texel inside the face next to the edge sits half a texel
// from it; its neighbour across the edge sits half a texel from the edge on
// the other face, at the same place along the edge.
CookieTap acrossEdge(int face, int i, int j, int n) {
  CookieTap tap{face, i, j, false, 0};
  const bool outI = i < 0 || i >= n, outJ = j < 0 || j >= n;
  if (!outI && !outJ) return tap;
  if (outI && outJ) {
    tap.corner = true;
    tap.i = std::clamp(i, 0, n - 1);
    tap.j = std::clamp(j, 0, n - 1);
    return tap;
  }
  const int ci = std::clamp(i, 0, n - 1), cj = std::clamp(j, 0, n - 1);
  const double s = 2.0 * (ci + 0.5) / n - 1.0, t = 2.0 * (cj + 0.5) / n - 1.0;
  Vec3 d = facePoint(face, s, t);
  const FaceAxes& a = kFaces[face];
  const int edgeAxis = outI ? a.sAxis : a.tAxis;
  d[a.major] = a.sign * (1.0 - 1.0 / n);
  d[edgeAxis] = d[edgeAxis] > 0 ? 1.0 : -1.0;
  const CookieCoordinates across = cubeCoordinates(d);
  tap.face = across.face;
  tap.i = std::clamp(int(std::floor(across.u * n)), 0, n - 1);
  tap.j = std::clamp(int(std::floor(across.v * n)), 0, n - 1);
  return tap;
}

}  // namespace

LightBasis lightBasis(const Vec3& direction) {
  LightBasis b;
  b.f = glm::normalize(direction);
  const Vec3 up = std::abs(b.f.y) > kBasisUpSwitch ? Vec3(0, 0, 1) : Vec3(0, 1, 0);
  b.r = glm::normalize(glm::cross(b.f, up));
  b.u = glm::cross(b.r, b.f);
  return b;
}

CookieCoordinates cubeCoordinates(const Vec3& d) {
  const Vec3 m = glm::abs(d);
  int face;
  if (m.x >= m.y && m.x >= m.z) face = d.x >= 0 ? 0 : 1;
  else if (m.y >= m.z) face = d.y >= 0 ? 2 : 3;
  else face = d.z >= 0 ? 4 : 5;
  const FaceAxes& a = kFaces[face];
  const double ma = m[a.major];
  CookieCoordinates c;
  c.face = face;
  c.u = (a.sSign * d[a.sAxis] / ma + 1.0) / 2.0;
  c.v = (a.tSign * d[a.tAxis] / ma + 1.0) / 2.0;
  return c;
}

double spotCookieScale(const Light& spot) { return 0.5 / std::tan(spot.spotAngleDeg * std::numbers::pi / 360.0); }

CookieCoordinates cookieCoordinates(const Light& light, const Vec3& p) {
  CookieCoordinates c;
  if (!light.cookie) return c;
  switch (light.type) {
    case LightType::Directional: {
      const LightBasis b = lightBasis(light.direction);
      c.u = glm::dot(p, b.r) / light.cookie->sizeX;
      c.v = glm::dot(p, b.u) / light.cookie->sizeY;
      return c;
    }
    case LightType::Spot: {
      const LightBasis b = lightBasis(light.direction);
      const Vec3 d = p - light.position;
      const double qz = glm::dot(d, b.f);
      if (qz <= 0) {
        c.outside = true;
        return c;
      }
      const double scale = spotCookieScale(light) / qz;
      c.u = 0.5 + glm::dot(d, b.r) * scale;
      c.v = 0.5 + glm::dot(d, b.u) * scale;
      return c;
    }
    case LightType::Point: return cubeCoordinates(p - light.position);
  }
  return c;
}

std::array<CookieTap, 4> cookieTaps(const Light& light, const CookieCoordinates& at) {
  const Cookie& cookie = *light.cookie;
  const CookieImage& image = *cookie.images[light.type == LightType::Point ? at.face : 0];
  const int w = image.width, h = image.height;
  const double x = at.u * w - 0.5, y = at.v * h - 0.5;
  const int i0 = int(std::floor(x)), j0 = int(std::floor(y));
  const double a = x - i0, b = y - j0;
  const int is[4] = {i0, i0 + 1, i0, i0 + 1}, js[4] = {j0, j0, j0 + 1, j0 + 1};
  const double weights[4] = {(1 - a) * (1 - b), a * (1 - b), (1 - a) * b, a * b};
  std::array<CookieTap, 4> taps;
  for (int k = 0; k < 4; ++k) {
    switch (light.type) {
      case LightType::Directional: taps[k] = {0, wrap(is[k], w), wrap(js[k], h), false, 0}; break;
      case LightType::Spot: taps[k] = {0, std::clamp(is[k], 0, w - 1), std::clamp(js[k], 0, h - 1), false, 0}; break;
      case LightType::Point: taps[k] = acrossEdge(at.face, is[k], js[k], w); break;
    }
    taps[k].weight = weights[k];
  }
  return taps;
}

double tapValue(const Cookie& cookie, const CookieTap& tap) {
  const CookieImage& image = *cookie.images[tap.face];
  if (!tap.corner) return image.at(tap.i, tap.j);
  // A corner: this face's corner texel and its neighbours across both edges.
  const int n = image.width;
  const int outI = tap.i == 0 ? -1 : n, outJ = tap.j == 0 ? -1 : n;
  const CookieTap acrossI = acrossEdge(tap.face, outI, tap.j, n);
  const CookieTap acrossJ = acrossEdge(tap.face, tap.i, outJ, n);
  return (image.at(tap.i, tap.j) + cookie.images[acrossI.face]->at(acrossI.i, acrossI.j) +
          cookie.images[acrossJ.face]->at(acrossJ.i, acrossJ.j)) /
         3.0;
}

double cookieValue(const Light& light, const Vec3& p) {
  if (!light.cookie) return 1.0;
  const CookieCoordinates at = cookieCoordinates(light, p);
  if (at.outside) return 0.0;
  return blendTaps(*light.cookie, cookieTaps(light, at));
}

double blendTaps(const Cookie& cookie, const std::array<CookieTap, 4>& taps) {
  double value = 0;
  for (const CookieTap& tap : taps) value += tap.weight * tapValue(cookie, tap);
  return value;
}

}  // namespace lighting
