#include "lighting/shadow_projection.h"

#include "lighting/light_math.h"
#include "lighting/light_space.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>

namespace lighting {

bool MapPoint::outsideMap() const {
  return behind || mu < 0 || mu > 1 || mv < 0 || mv > 1 || depth < 0 || depth > 1;
}

double ShadowView::depthOfViewDepth(double z) const {
  if (!perspective) return (z / halfWidth + 1.0) / 2.0;
  // Vulkan's z/w: far (z - near) / ((far - near) z).
  return farPlane * (z - nearPlane) / ((farPlane - nearPlane) * z);
}

MapPoint ShadowView::project(const Vec3& q) const {
  const Vec3 d = q - origin;
  const double x = glm::dot(d, r), y = glm::dot(d, u), z = glm::dot(d, f);
  MapPoint m;
  if (!perspective) {
    m.mu = (x / halfWidth + 1.0) / 2.0;
    m.mv = (y / halfWidth + 1.0) / 2.0;
    m.depth = depthOfViewDepth(z);
    return m;
  }
  if (z <= 0) {
    m.behind = true;
    return m;
  }
  m.mu = (x / (z * halfWidth) + 1.0) / 2.0;
  m.mv = (y / (z * halfWidth) + 1.0) / 2.0;
  m.depth = depthOfViewDepth(z);
  return m;
}

TexelRay ShadowView::rayThrough(double mu, double mv) const {
  const double x = 2.0 * mu - 1.0, y = 2.0 * mv - 1.0;
  TexelRay t;
  if (!perspective) {
    // Parallel rays from the box's near face (depth 0) to its far face (depth 1).
    t.ray = {origin + halfWidth * (x * r + y * u - f), f};
    t.tMin = 0;
    t.tMax = 2.0 * halfWidth;
    return t;
  }
  const Vec3 along = f + halfWidth * (x * r + y * u);
  t.ray = {origin, glm::normalize(along)};
  const double cosine = glm::dot(t.ray.direction, f);
  t.tMin = nearPlane / cosine;
  t.tMax = farPlane / cosine;
  return t;
}

glm::dmat4 ShadowView::clipFromCameraRelative(const Vec3& cameraPosition) const {
  // Rows of the light's view: p_view = B (p + camera - origin).
  const Vec3 offset = cameraPosition - origin;
  auto row = [&](const Vec3& axis) { return glm::dvec4(axis, glm::dot(axis, offset)); };
  const glm::dvec4 rx = row(r), ry = row(u), rz = row(f);
  glm::dvec4 cx, cy, cz, cw;
  if (!perspective) {
    cx = rx / halfWidth;
    cy = ry / halfWidth;
    cz = rz / (2.0 * halfWidth) + glm::dvec4(0, 0, 0, 0.5);
    cw = glm::dvec4(0, 0, 0, 1);
  } else {
    const double a = farPlane / (farPlane - nearPlane);
    cx = rx / halfWidth;
    cy = ry / halfWidth;
    cz = rz * a - glm::dvec4(0, 0, 0, a * nearPlane);
    cw = rz;
  }
  // GLM is column-major: m[column][row].
  glm::dmat4 m(0.0);
  for (int c = 0; c < 4; ++c) {
    m[c][0] = cx[c];
    m[c][1] = cy[c];
    m[c][2] = cz[c];
    m[c][3] = cw[c];
  }
  return m;
}

int ShadowProjection::viewOf(const Vec3& q) const {
  if (type != LightType::Point) return 0;
  return cubeFacePoint(q - lightPosition).face;
}

Vec3 ShadowProjection::towardLight(const Vec3& p) const {
  if (type == LightType::Directional) return -lightDirection;
  return glm::normalize(lightPosition - p);
}

Vec3 ShadowProjection::offsetReceiver(const Vec3& p, const Vec3& N) const {
  return p + spec.normalBias * N + spec.depthBias * towardLight(p);
}

namespace {

// A perspective view from the light along f, near = shadow_map.near, far = range.
ShadowView perspectiveView(const Light& light, const Vec3& r, const Vec3& u, const Vec3& f, double halfWidth) {
  ShadowView v;
  v.perspective = true;
  v.origin = light.position;
  v.r = r;
  v.u = u;
  v.f = f;
  v.halfWidth = halfWidth;
  v.nearPlane = light.shadowMap->nearPlane;
  v.farPlane = light.range;
  return v;
}

}  // namespace

ShadowProjection shadowProjection(const Scene& scene, int light) {
  const Light& l = scene.lights[light];
  ShadowProjection p;
  p.light = light;
  p.type = l.type;
  p.spec = *l.shadowMap;
  p.lightPosition = l.position;
  p.lightDirection = l.direction;
  switch (l.type) {
    case LightType::Directional: {
      const LightBasis b = lightBasis(l.direction);
      ShadowView v;
      v.origin = p.spec.center;
      v.r = b.r;
      v.u = b.u;
      v.f = b.f;
      v.halfWidth = p.spec.extent;
      v.nearPlane = -p.spec.extent;
      v.farPlane = p.spec.extent;
      p.views.push_back(v);
      break;
    }
    case LightType::Spot: {
      const LightBasis b = lightBasis(l.direction);
      p.views.push_back(perspectiveView(l, b.r, b.u, b.f, std::tan(l.spotAngleDeg * std::numbers::pi / 360.0)));
      break;
    }
    case LightType::Point:
      for (int face = 0; face < kCubeFaceCount; ++face) {
        const CubeFaceFrame frame = cubeFaceFrame(face);
        p.views.push_back(perspectiveView(l, frame.sAxis, frame.tAxis, frame.axis, 1.0));  // 90 degrees
      }
      break;
  }
  return p;
}

double shadowFade(double shadowDistance, double viewDepth) {
  if (shadowDistance <= 0) return 0;
  return saturate((viewDepth - 0.8 * shadowDistance) / (0.2 * shadowDistance));
}

double shadowAttenuation(double s, double strength, double fade) {
  return saturate(1.0 + strength * (s - 1.0) + fade);
}

}  // namespace lighting
