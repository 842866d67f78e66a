#include "scene_input/look_at.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace scene_input {
namespace {

// Below this sine of the angle between up and the view direction, lookAt has
// no usable basis.
constexpr double kMinUpSine = 1e-6;

}  // namespace

std::optional<lighting::Vec3> unitVector(const lighting::Vec3& v) {
  // Dividing by the largest component first keeps tiny and huge vectors from
  // under- or overflowing.
  const double largest = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
  if (largest == 0) return std::nullopt;
  const lighting::Vec3 scaled = v / largest;
  return scaled / glm::length(scaled);
}

std::optional<LookAtProblem> lookAtProblem(const lighting::Vec3& position, const lighting::Vec3& target,
                                           const lighting::Vec3& up) {
  const auto view = unitVector(target - position);
  if (!view) return LookAtProblem::SamePoint;
  const auto upDirection = unitVector(up);
  if (!upDirection || glm::length(glm::cross(*view, *upDirection)) < kMinUpSine) return LookAtProblem::UpParallel;
  return std::nullopt;
}

}  // namespace scene_input
