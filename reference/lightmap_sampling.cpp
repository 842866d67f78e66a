#include "reference/lightmap_sampling.h"

#include "reference/tolerance_model.h"

#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>

namespace reference {

namespace tol = tolerance;

Vec2 lightmapUvOfWorldPoint(const lighting::MeshSpec& plane, const lighting::ObjectTransform& transform,
                            const Vec3& world) {
  // world = R (s local) + t, R orthonormal: local = R^T (world - t) / s.
  const Vec3 local = glm::transpose(transform.rotation) * (world - transform.translate) / transform.scale;
  return lighting::planeLightmapUv(plane, local);
}

TexelFootprint texelFootprint(int resolution, const Vec2& uv) {
  // Texel centres sit at (i + 0.5) / N: shift by half a texel, then the two
  // neighbours in each direction, clamped to the edge.
  const double x = uv.x * resolution - 0.5, y = uv.y * resolution - 0.5;
  const double x0 = std::floor(x), y0 = std::floor(y);
  const int last = resolution - 1;
  TexelFootprint f;
  f.fx = x - x0;
  f.fy = y - y0;
  f.i0 = std::clamp(int(x0), 0, last);
  f.i1 = std::clamp(int(x0) + 1, 0, last);
  f.j0 = std::clamp(int(y0), 0, last);
  f.j1 = std::clamp(int(y0) + 1, 0, last);
  return f;
}

double filteringErrorBound(double spread, double magnitude, int resolution, double weightPrecision) {
  const double u = tol::kStepRoundoff;
  // Inside one cell the bilinear value changes by at most `spread` per texel
  // along each axis, i.e. N x spread per unit of UV.
  const double fromWeights = tol::kFilterWeightErrorsPerSample * weightPrecision * spread;
  const double fromUv = 2.0 * resolution * spread * tol::kLightmapUvRoundingSteps * u;
  const double fromBlend = tol::kFilterBlendRoundingSteps * u * magnitude;
  return fromWeights + fromUv + fromBlend;
}

Vec4 filteringErrorBound(const lighting::BilinearSample& sample, int resolution, double weightPrecision) {
  Vec4 bound(0.0);
  for (int c = 0; c < 4; ++c) {
    // The value is a convex blend of the four texels, so none is larger in
    // magnitude than |value| + spread.
    const double magnitude = std::abs(sample.value[c]) + sample.spread[c];
    bound[c] = filteringErrorBound(sample.spread[c], magnitude, resolution, weightPrecision);
  }
  return bound;
}

}  // namespace reference
