#include "lighting/transform.h"

#include <cmath>
#include <numbers>

namespace lighting {
namespace {

// Standard right-handed rotations about one axis (counter-clockwise when the
// axis points at the viewer). GLM matrices are column-major: m[col][row].
glm::dmat3 rotationX(double rad) {
  const double c = std::cos(rad), s = std::sin(rad);
  return glm::dmat3(1, 0, 0,  0, c, s,  0, -s, c);
}
glm::dmat3 rotationY(double rad) {
  const double c = std::cos(rad), s = std::sin(rad);
  return glm::dmat3(c, 0, -s,  0, 1, 0,  s, 0, c);
}
glm::dmat3 rotationZ(double rad) {
  const double c = std::cos(rad), s = std::sin(rad);
  return glm::dmat3(c, s, 0,  -s, c, 0,  0, 0, 1);
}
double radians(double deg) { return deg * std::numbers::pi / 180.0; }

}  // namespace

glm::dmat3 rotationMatrix(const Vec3& rotateDeg) {
  return rotationY(radians(rotateDeg.y)) * rotationX(radians(rotateDeg.x)) *
         rotationZ(radians(rotateDeg.z));
}

ObjectTransform objectTransform(const Transform& t) {
  return ObjectTransform{rotationMatrix(t.rotateDeg), t.scale, t.translate};
}

}  // namespace lighting
