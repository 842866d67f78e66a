#include "reference/surface_inputs.h"

#include "reference/light_terms.h"

#include <glm/geometric.hpp>

#include <algorithm>

namespace reference {
namespace {

using terms::Vec3Of;

// a[0] b[0] + ... + a[n-1] b[n-1] in any order and with any contraction
// (OpMatrixTimesVector and dot are inherited from the sum of products): each
// product's inputs' errors and rounding, then n - 1 additions of partial sums
// no larger than the sum of the products' magnitudes.
FloatBound sumOfProducts(const FloatBound* a, const FloatBound* b, int n) {
  FloatBound sum;
  double carried = 0, magnitudes = 0;
  for (int i = 0; i < n; ++i) {
    const FloatBound p = a[i] * b[i];
    sum.value += p.value;
    sum.lo += p.lo;
    sum.hi += p.hi;
    carried += p.error;
    magnitudes += p.largestResult();
  }
  sum.error = carried + double(n - 1) * FloatBound::rounding(Float32Precision::kAddUlps, magnitudes);
  return sum;
}

Vec3Of<FloatBound> unitVector(const Vec3Of<FloatBound>& v) { return v * inverseSqrt(terms::dotProduct(v, v)); }

const FloatBound& at(const Vec3Of<FloatBound>& v, int i) { return i == 0 ? v.x : i == 1 ? v.y : v.z; }

double largestError(const Vec3Of<FloatBound>& v) { return std::max({v.x.error, v.y.error, v.z.error}); }

// What forward.vert computes of one vertex: the camera-relative position
// (objectData.model * vec4(inPosition, 1)), its clip w (viewProjection's
// last row times that), and the normal (normalize(normalMatrix * inNormal)).
struct VertexOutputs {
  Vec3Of<FloatBound> position;
  FloatBound w;
  Vec3Of<FloatBound> normal;
  double rotatedNormalError = 0;  // the rotated normal's, before normalize (which only scales it)
};

VertexOutputs vertexStage(const lighting::ObjectTransform& t, const Vec3& camera, const glm::dmat4& viewProjection,
                          const MeshVertex& vertex) {
  // The uploaded matrices (lighting::packObjectBlock: rotation * scale, then
  // translate - camera; the rotation for normals), entry by entry as float.
  const glm::dmat3 linear = t.rotation * t.scale;
  const Vec3 translate = t.translate - camera;
  const FloatBound local[4] = {FloatBound::uploaded(vertex.local.x), FloatBound::uploaded(vertex.local.y),
                               FloatBound::uploaded(vertex.local.z), FloatBound(1.0)};
  FloatBound position[4];
  for (int i = 0; i < 3; ++i) {
    const FloatBound row[4] = {FloatBound::uploaded(linear[0][i]), FloatBound::uploaded(linear[1][i]),
                               FloatBound::uploaded(linear[2][i]), FloatBound::uploaded(translate[i])};
    position[i] = sumOfProducts(row, local, 4);
  }
  position[3] = FloatBound(1.0);
  VertexOutputs out;
  out.position = {position[0], position[1], position[2]};
  const FloatBound lastRow[4] = {FloatBound::uploaded(viewProjection[0][3]), FloatBound::uploaded(viewProjection[1][3]),
                                 FloatBound::uploaded(viewProjection[2][3]), FloatBound::uploaded(viewProjection[3][3])};
  out.w = sumOfProducts(lastRow, position, 4);
  const FloatBound localNormal[3] = {FloatBound::uploaded(vertex.localNormal.x),
                                     FloatBound::uploaded(vertex.localNormal.y),
                                     FloatBound::uploaded(vertex.localNormal.z)};
  FloatBound normal[3];
  for (int i = 0; i < 3; ++i) {
    const FloatBound row[3] = {FloatBound::uploaded(t.rotation[0][i]), FloatBound::uploaded(t.rotation[1][i]),
                               FloatBound::uploaded(t.rotation[2][i])};
    normal[i] = sumOfProducts(row, localNormal, 3);
  }
  out.rotatedNormalError = std::max({normal[0].error, normal[1].error, normal[2].error});
  out.normal = unitVector(Vec3Of<FloatBound>{normal[0], normal[1], normal[2]});
  return out;
}

// The normal forward.frag normalises. normalize() takes out any factor
// common to the blend (the weights' normalisation, and any error the weights
// and the vertex normals' lengths share), so what turns the normal is: the
// vertex normals' own turn (their rotation's rounding; normalize in the
// vertex stage only scales), the weights' and lengths' differences acting on
// the differences between the vertices' normals (none on a flat piece), and
// the blend's additions. The fragment's normalize then adds its own
// rounding, in direction and length.
double blendedNormalError(const std::array<VertexOutputs, 3>& v, const FloatBound (&a)[3], const FloatBound (&w)[3]) {
  double turn = 0, lengthError = 0, weightError = 0, weightSum = 0;
  for (int k = 0; k < 3; ++k) {
    turn = std::max(turn, v[k].rotatedNormalError);
    lengthError = std::max(lengthError, largestError(v[k].normal));
    const FloatBound weight = quotient(a[k], w[k]);
    weightSum += weight.value;
    weightError = std::max(weightError, weight.error);
  }
  const double relativeWeightError = weightError / weightSum + lengthError;
  Vec3Of<FloatBound> blend;
  FloatBound* out[3] = {&blend.x, &blend.y, &blend.z};
  for (int i = 0; i < 3; ++i) {
    double value = 0, magnitudes = 0, spread = 0;
    for (int k = 0; k < 3; ++k) {
      const double weight = a[k].value / w[k].value / weightSum;
      value += weight * at(v[k].normal, i).value;
      magnitudes += weight * std::abs(at(v[k].normal, i).value);
    }
    for (int k = 0; k < 3; ++k) spread = std::max(spread, std::abs(at(v[k].normal, i).value - value));
    // Two additions of the weighted terms, the weights' differences on the
    // spread, the vertex normals' turn.
    const double error = turn + 2.0 * relativeWeightError * spread +
                         2.0 * FloatBound::rounding(Float32Precision::kAddUlps, magnitudes);
    *out[i] = FloatBound::input(value, error);
  }
  return largestError(unitVector(blend));
}

SurfaceErrors blendedInputErrors(const std::array<VertexOutputs, 3>& v, const std::array<double, 3>& b,
                                 double nearestW) {
  // The screen barycentrics of the point whose 3D barycentrics are b:
  // a_k proportional to b_k w_k. A vertex behind the near plane is one the
  // clipper replaced by vertices on it: its w is taken there, exactly.
  // Vulkan states no precision for clipping; a clipper that computed the new
  // w from a far vertex in front and one far behind would lose most of it to
  // cancellation (docs/tolerances.md, "What is not modelled").
  double w[3], wError[3], weightSum = 0;
  for (int k = 0; k < 3; ++k) {
    const bool clipped = v[k].w.value < nearestW;
    w[k] = clipped ? nearestW : v[k].w.value;
    wError[k] = clipped ? 0.0 : v[k].w.error;
    weightSum += b[k] * w[k];
  }
  // Vulkan's perspective-correct blend (Basic Polygon Rasterization):
  // (a f_a / w_a + a_b f_b / w_b + a_c f_c / w_c) / (a / w_a + ...), with the
  // screen barycentrics a = A(p p_b p_c) / A(p_a p_b p_c), a division of exact
  // fixed-point areas; each operation at the table's allowance.
  FloatBound a[3], clipW[3];
  for (int k = 0; k < 3; ++k) {
    a[k] = quotient(FloatBound::input(b[k] * w[k] / weightSum, 0.0), FloatBound::input(1.0, 0.0));
    clipW[k] = FloatBound::input(w[k], wError[k]);
  }
  // The position, with the weights' errors taken together rather than each
  // alone: write q_k = a_k / w_k as the blend computes it, off by a relative
  // rho_k. The formula's value is sum q_k v_k / sum q_k, and with lambda_k =
  // q_k / sum q_k its error from the weights is
  //   sum_k lambda_k (rho_k - mean rho) (v_k - p) / (1 + mean rho):
  // what the weights share cancels between numerator and denominator, and
  // what they do not moves the point along the triangle, by at most twice
  // the largest rho times sum_k lambda_k |v_k - p|. Then each operation's
  // own rounding: the products q_k v_k (1 ULP each) and their two additions
  // (of a partial sum up to sum lambda_k |v_k|, relative to the
  // denominator), the denominator's two additions and the division (of
  // |p|), and the vertices' own errors.
  double rho = 0, lambda[3];
  for (int k = 0; k < 3; ++k) {
    const FloatBound q = quotient(a[k], clipW[k]);
    rho = std::max(rho, q.error / q.value);
    lambda[k] = q.value;
  }
  const double lambdaSum = lambda[0] + lambda[1] + lambda[2];
  for (double& l : lambda) l /= lambdaSum;
  double positionError = 0;
  for (int i = 0; i < 3; ++i) {
    double p = 0, vertexError = 0, spread = 0, magnitudes = 0;
    for (int k = 0; k < 3; ++k) {
      const FloatBound& vk = at(v[k].position, i);
      p += lambda[k] * vk.value;
      vertexError += lambda[k] * vk.error;
      magnitudes += lambda[k] * vk.largestResult();
    }
    for (int k = 0; k < 3; ++k) spread += lambda[k] * std::abs(at(v[k].position, i).value - p);
    const double error =
        vertexError + 2.0 * rho * spread / (1.0 - rho) +
        FloatBound::rounding(Float32Precision::kMultiplyUlps + 2.0 * Float32Precision::kAddUlps, magnitudes) +
        FloatBound::rounding(2.0 * Float32Precision::kAddUlps + Float32Precision::kQuotientUlps, std::abs(p));
    positionError = std::max(positionError, error);
  }
  return {positionError, blendedNormalError(v, a, clipW)};
}

}  // namespace

SurfaceErrors fragmentInputErrors(const lighting::ObjectTransform& transform, const Vec3& camera,
                                  const glm::dmat4& viewProjection, double nearestW,
                                  const std::array<MeshVertex, 3>& vertices, const std::array<double, 3>& b) {
  std::array<VertexOutputs, 3> outputs;
  for (int k = 0; k < 3; ++k) outputs[k] = vertexStage(transform, camera, viewProjection, vertices[k]);
  return blendedInputErrors(outputs, b, nearestW);
}

SurfaceErrors vertexInputErrors(const lighting::ObjectTransform& transform, const Vec3& camera,
                                const MeshVertex& vertex) {
  const VertexOutputs out = vertexStage(transform, camera, glm::dmat4(1.0), vertex);
  return {largestError(out.position), largestError(out.normal)};
}

SurfaceErrors inputErrorsOfMagnitude(double magnitude) {
  lighting::ObjectTransform t;
  t.translate = Vec3(magnitude / 2);
  MeshVertex vertex;
  vertex.local = Vec3(magnitude / 2);
  std::array<VertexOutputs, 3> outputs;
  for (int k = 0; k < 3; ++k) outputs[k] = vertexStage(t, Vec3(0.0), glm::dmat4(1.0), vertex);
  return blendedInputErrors(outputs, {1.0 / 3, 1.0 / 3, 1.0 / 3}, 1.0);
}

}  // namespace reference
