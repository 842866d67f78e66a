// Object transforms (SPEC 1): R = Ry(y) * Rx(x) * Rz(z), then uniform scale,
// then translate. Normals are rotated by R only.
#pragma once

#include "lighting/scene.h"

#include <glm/mat3x3.hpp>

namespace lighting {

glm::dmat3 rotationMatrix(const Vec3& rotateDeg);

struct ObjectTransform {
  glm::dmat3 rotation{1.0};
  double scale = 1;
  Vec3 translate{0, 0, 0};

  Vec3 applyToPoint(const Vec3& local) const { return rotation * (scale * local) + translate; }
  Vec3 applyToNormal(const Vec3& localNormal) const { return rotation * localNormal; }
};

ObjectTransform objectTransform(const Transform& t);

}  // namespace lighting
