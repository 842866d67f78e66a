#include "reference/deferred_buffers.h"

#include "reference/tolerance_model.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace reference {

using namespace lighting;
namespace tol = tolerance;

namespace {

// The decode: -log2(max(x, 1/255)).
double decode(double x) { return -std::log2(std::max(x, tol::kLdr8SmallestDecoded)); }

}  // namespace

double decodedLightSum(DeferredBuffer buffer, double lightSum) {
  if (buffer != DeferredBuffer::Ldr8) return lightSum;
  return decode(std::exp2(-lightSum));
}

double hdr16BlendBound(double lightSum, int contributing) {
  // Each contributing blend rounds its source (2^-10 c_j) and the new sum
  // (2^-10 s_j <= 2^-10 S, the terms being >= 0), each with the flush floor.
  const double k = contributing;
  return (k + 1.0) * tol::kHalfRounding * std::abs(lightSum) + 2.0 * k * tol::kHalfFlushFloor;
}

double ldr8DecodeBound(double lightSum, int contributing, double sumBound) {
  // Nothing added, and no term that float arithmetic could make non-zero:
  // the clear value 1 stays exact, and log2(1) is 0 within log2's absolute
  // 2^-21 inside [0.5, 2] ("Precision of GLSL.std.450 Instructions"): the
  // decode's error alone.
  if (contributing <= 0 && sumBound <= 0) return tol::kLdr8DecodeAbsError;
  const double u = tol::kUnitRoundoff, step = tol::kStepRoundoff;
  // A term that is exactly 0 here may reach the GPU as a tiny positive value
  // (within sumBound): at least one blend.
  const double k = std::max(contributing, 1);
  const double x = std::exp2(-lightSum);
  // The sum's own error e moves the encoded value within
  // [2^-(S+e), 2^-(S-e)] (exactly, not linearised), then exp2's ULPs and one
  // product per blend, relative; a UNORM target clamps at 1.
  const double arithmetic = 2.0 * u * (tol::kExp2Ulps * k + tol::kExp2UlpsPerUnitArgument * lightSum) + k * step;
  const double low = std::exp2(-(lightSum + sumBound)) * (1.0 - arithmetic);
  const double high = std::min(1.0, std::exp2(-(lightSum - sumBound)) * (1.0 + arithmetic));
  // The first blend lands on the exact clear value 1: one conversion; every
  // later one converts its source and the product: two.
  const double rounding = (2.0 * k - 1.0) * tol::kUnormRoundingError;
  // The buffer holds a grid point n / 255 in [low - rounding, high + rounding];
  // the decode is monotone, so the extreme grid points give the extreme values.
  const double nLow = std::max(0.0, std::ceil((low - rounding) * tol::kUnormSteps));
  const double nHigh = std::min(tol::kUnormSteps, std::floor((high + rounding) * tol::kUnormSteps));
  const double exact = decode(x);
  double bound = 0.0;
  if (nLow <= nHigh) {
    bound = std::max(std::abs(decode(nLow / tol::kUnormSteps) - exact), std::abs(decode(nHigh / tol::kUnormSteps) - exact));
  }
  return bound + tol::kLdr8DecodeAbsError;
}

double reconstructionPositionError(const CameraView& view, const Vec3& p, double vertexSnap) {
  const double u = tol::kStepRoundoff;
  const Camera& c = view.camera;
  const Vec3 offset = p - c.position;
  const double distance = glm::length(offset);
  const double zView = glm::dot(offset, view.forward);
  const bool perspective = c.projection == Projection::Perspective;
  // Along the ray through the pixel: a view-depth error dz moves the point by
  // dz / cos(angle between ray and view axis); orthographic rays are the axis.
  const double cosine = perspective && distance > 0 ? std::max(zView / distance, 1e-6) : 1.0;
  const double depthPerWindowDepth = perspective
                                         ? zView * zView * (c.farPlane - c.nearPlane) / (c.farPlane * c.nearPlane)
                                         : (c.farPlane - c.nearPlane);
  const double fromDepth = tol::kReconstructionDepthSteps * u * depthPerWindowDepth / cosine;
  // Across the ray: NDC error times the view's half-extent at that depth, two axes.
  const double halfHeight = perspective ? zView * std::tan(c.fovYDeg * std::numbers::pi / 360.0) : c.orthoHeight / 2.0;
  const double halfExtent = halfHeight * std::max(1.0, view.aspect());
  const double fromNdc = tol::kReconstructionNdcSteps * u * std::numbers::sqrt2 * halfExtent;
  const double fromMatrix = tol::kReconstructionMatrixSteps * u * distance;
  // Snapping: the G-buffer pass stores the depth its snapped surface
  // triangle has at the pixel centre, the depth of the surface point S(a)
  // seen through a point a up to vertexSnap pixels away on each axis
  // (tolerance_model.h); the light pass rebuilds the point on the centre's
  // own ray (gl_FragCoord, shaders/deferred_light.frag) at that depth: S(a)
  // moved across the view axis by |a - centre| pixels at that depth. S(a) is
  // a point the sub-pixel term already admits; the move is a position error.
  const double fromSnapping = vertexSnap * std::numbers::sqrt2 * view.pixelSizeAt(p);
  return fromDepth + fromNdc + fromMatrix + fromSnapping;
}

}  // namespace reference
