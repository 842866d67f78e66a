#include "lighting/cookie_packing.h"

#include "lighting/cookie.h"

#include <cmath>

namespace lighting {
namespace {

// The map of one light, in double.
glm::dmat4 toCookieSpace(const Frame& frame, const Light& light) {
  const Vec3 camera = frame.view.camera.position;
  glm::dmat4 m(1.0);  // columns; m[c][r]
  auto setRow = [&m](int row, const Vec3& axis, double offset) {
    for (int c = 0; c < 3; ++c) m[c][row] = axis[c];
    m[3][row] = offset;
  };
  switch (light.type) {
    case LightType::Directional: {
      const LightBasis b = lightBasis(light.direction);
      const double cu = glm::dot(camera, b.r) / light.cookie->sizeX;
      const double cv = glm::dot(camera, b.u) / light.cookie->sizeY;
      setRow(0, b.r / light.cookie->sizeX, cu - std::floor(cu));
      setRow(1, b.u / light.cookie->sizeY, cv - std::floor(cv));
      setRow(2, Vec3(0.0), 0.0);
      break;
    }
    case LightType::Spot: {
      const LightBasis b = lightBasis(light.direction);
      const Vec3 offset = camera - light.position;  // p_world - position = p_rel + offset
      setRow(0, b.r, glm::dot(offset, b.r));
      setRow(1, b.u, glm::dot(offset, b.u));
      setRow(2, b.f, glm::dot(offset, b.f));
      break;
    }
    case LightType::Point: {
      const Vec3 offset = camera - light.position;
      setRow(0, Vec3(1, 0, 0), offset.x);
      setRow(1, Vec3(0, 1, 0), offset.y);
      setRow(2, Vec3(0, 0, 1), offset.z);
      break;
    }
  }
  return m;
}

GpuCookie packCookie(const Frame& frame, int sceneLight, int textureIndex) {
  const Light& light = frame.scene().lights[sceneLight];
  GpuCookie g;
  g.toCookie = toGpuMat4(toCookieSpace(frame, light));
  const GpuCookieKind kind = light.type == LightType::Directional ? GpuCookieKind::Directional
                             : light.type == LightType::Spot      ? GpuCookieKind::Spot
                                                                  : GpuCookieKind::Point;
  const double spotScale = light.type == LightType::Spot ? spotCookieScale(light) : 0.0;
  g.params = {float(int(kind)), float(spotScale), float(textureIndex), 0.0f};
  return g;
}

}  // namespace

GpuCookieBlock packCookieBlock(const Frame& frame) {
  GpuCookieBlock block;
  const CookieSlots& slots = frame.cookies;
  for (int s = 0; s < int(slots.textureLights.size()); ++s) block.cookies[s] = packCookie(frame, slots.textureLights[s], s);
  for (int s = 0; s < int(slots.cubeLights.size()); ++s)
    block.cookies[kMaxCookieTextures + s] = packCookie(frame, slots.cubeLights[s], s);
  return block;
}

int cookieBlockSlot(const Frame& frame, int sceneLight) {
  // A frame made without slots (no cookie anywhere) has an empty table.
  if (sceneLight >= int(frame.cookies.slotOfLight.size())) return -1;
  const int slot = frame.cookies.slotOfLight[sceneLight];
  if (slot < 0) return -1;
  return frame.scene().lights[sceneLight].type == LightType::Point ? kMaxCookieTextures + slot : slot;
}

}  // namespace lighting
