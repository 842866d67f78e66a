#include "lighting/baked_lighting.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>

namespace lighting {

Vec4 TexelMap::texel(int i, int j) const {
  i = std::clamp(i, 0, resolution - 1);
  j = std::clamp(j, 0, resolution - 1);
  const float* t = &texels[(std::size_t(j) * std::size_t(resolution) + std::size_t(i)) * 4];
  return {t[0], t[1], t[2], t[3]};
}

BilinearSample sampleBilinear(const TexelMap& map, const Vec2& uv) {
  // Texel centres sit at (i + 0.5) / N: shift by half a texel, then blend the
  // two neighbours in each direction (the GPU's LINEAR filter, clamp to edge).
  const double x = uv.x * map.resolution - 0.5;
  const double y = uv.y * map.resolution - 0.5;
  const double x0 = std::floor(x), y0 = std::floor(y);
  const double fx = x - x0, fy = y - y0;
  const int i = int(x0), j = int(y0);
  const Vec4 t00 = map.texel(i, j), t10 = map.texel(i + 1, j);
  const Vec4 t01 = map.texel(i, j + 1), t11 = map.texel(i + 1, j + 1);
  BilinearSample s;
  s.value = (t00 * (1 - fx) + t10 * fx) * (1 - fy) + (t01 * (1 - fx) + t11 * fx) * fy;
  s.spread = glm::max(glm::max(t00, t10), glm::max(t01, t11)) - glm::min(glm::min(t00, t10), glm::min(t01, t11));
  return s;
}

Vec2 planeLightmapUv(const MeshSpec& plane, const Vec3& localPosition) {
  return {localPosition.x / plane.planeSizeX + 0.5, localPosition.z / plane.planeSizeZ + 0.5};
}

Vec3 planeTexelCentreLocal(const MeshSpec& plane, int resolution, int i, int j) {
  const double u = (i + 0.5) / resolution, v = (j + 0.5) / resolution;
  return {(u - 0.5) * plane.planeSizeX, 0.0, (v - 0.5) * plane.planeSizeZ};
}

}  // namespace lighting
