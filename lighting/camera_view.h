// The camera of one frame (SPEC 1 and 2 `frames`), in double precision: its
// basis, the ray through a pixel, and the frustum planes used by light culling.
#pragma once

#include "lighting/scene.h"

#include <glm/mat4x4.hpp>

#include <array>

namespace lighting {

struct Ray {
  Vec3 origin;
  Vec3 direction;  // unit length
};

// A plane with an inward unit normal: signedDistance(p) >= 0 inside the frustum.
struct FrustumPlane {
  Vec3 normal;
  double offset = 0;
  double signedDistance(const Vec3& p) const;
};

struct CameraView {
  Camera camera;  // position and target already moved along the path for this frame
  int width = 0, height = 0;
  Vec3 forward, right, up;  // orthonormal; the view looks down -Z, i.e. along `forward`

  double aspect() const { return double(width) / double(height); }
  // NDC of a point in continuous pixel coordinates (pixel (i, j) has its centre
  // at (i + 0.5, j + 0.5), row 0 at the top): SPEC 1.
  Ray rayThroughPixel(double px, double py) const;
  Ray rayThroughNdc(double ndcX, double ndcY) const;
  // Distance in front of the camera along the view axis.
  double viewDepth(const Vec3& p) const;
  // The side of one pixel, in world units, across the view axis at p's view depth.
  double pixelSizeAt(const Vec3& p) const;
  std::array<FrustumPlane, 6> frustumPlanes() const;
  // World-minus-camera-position to clip space (x right, y up in NDC, depth 0..1).
  // Translation is left out on purpose: backends upload positions relative to
  // the camera, so far from the origin nothing large reaches float32 (SPEC 7).
  glm::dmat4 cameraRelativeViewProjection() const;
};

// The camera of frame `frame` (0-based) of the scene's `frames`.
CameraView cameraViewForFrame(const Scene& scene, int frame);

}  // namespace lighting
