#include "lighting/cookie.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lighting {
namespace {

int wrap(int i, int n) { return ((i % n) + n) % n; }

CookieTap acrossEdge(int face, int i, int j, int n) {
  const CubeTexel texel = cubeTexelAcrossEdge(face, i, j, n);
  return {texel.face, texel.i, texel.j, texel.corner, 0};
}

}  // namespace

CookieCoordinates cubeCoordinates(const Vec3& d) {
  const CubeFacePoint at = cubeFacePoint(d);
  CookieCoordinates c;
  c.face = at.face;
  c.u = at.u;
  c.v = at.v;
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
