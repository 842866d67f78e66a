#include "lighting/camera_view.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lighting {

double FrustumPlane::signedDistance(const Vec3& p) const { return glm::dot(normal, p) + offset; }

Ray CameraView::rayThroughPixel(double px, double py) const {
  return rayThroughNdc(2.0 * px / width - 1.0, 1.0 - 2.0 * py / height);
}

Ray CameraView::rayThroughNdc(double ndcX, double ndcY) const {
  if (camera.projection == Projection::Perspective) {
    const double tanY = std::tan(camera.fovYDeg * std::numbers::pi / 360.0);
    const Vec3 dir = forward + (ndcX * tanY * aspect()) * right + (ndcY * tanY) * up;
    return {camera.position, glm::normalize(dir)};
  }
  const double halfH = camera.orthoHeight / 2, halfW = halfH * aspect();
  return {camera.position + (ndcX * halfW) * right + (ndcY * halfH) * up, forward};
}

double CameraView::viewDepth(const Vec3& p) const { return glm::dot(p - camera.position, forward); }

double CameraView::pixelSizeAt(const Vec3& p) const {
  const double halfHeight = camera.projection == Projection::Perspective
                                ? viewDepth(p) * std::tan(camera.fovYDeg * std::numbers::pi / 360.0)
                                : camera.orthoHeight / 2;
  return 2.0 * halfHeight / double(height);
}

std::array<FrustumPlane, 6> CameraView::frustumPlanes() const {
  const Vec3& pos = camera.position;
  auto through = [](const Vec3& n, const Vec3& point) { return FrustumPlane{n, -glm::dot(n, point)}; };
  std::array<FrustumPlane, 6> planes;
  planes[0] = through(forward, pos + camera.nearPlane * forward);
  planes[1] = through(-forward, pos + camera.farPlane * forward);
  if (camera.projection == Projection::Perspective) {
    const double ty = std::tan(camera.fovYDeg * std::numbers::pi / 360.0), tx = ty * aspect();
    // A side plane contains the camera position; its inward normal is
    // perpendicular to the frustum's edge direction (e.g. forward - tx*right).
    planes[2] = through(glm::normalize(right + tx * forward), pos);
    planes[3] = through(glm::normalize(-right + tx * forward), pos);
    planes[4] = through(glm::normalize(up + ty * forward), pos);
    planes[5] = through(glm::normalize(-up + ty * forward), pos);
  } else {
    const double halfH = camera.orthoHeight / 2, halfW = halfH * aspect();
    planes[2] = through(right, pos - halfW * right);
    planes[3] = through(-right, pos + halfW * right);
    planes[4] = through(up, pos - halfH * up);
    planes[5] = through(-up, pos + halfH * up);
  }
  return planes;
}

glm::dmat4 CameraView::cameraRelativeViewProjection() const {
  // View: rows are the basis vectors; -forward is view +Z.
  glm::dmat4 view(1.0);
  for (int c = 0; c < 3; ++c) {
    view[c][0] = right[c];
    view[c][1] = up[c];
    view[c][2] = -forward[c];
  }
  const double n = camera.nearPlane, f = camera.farPlane;
  glm::dmat4 proj(0.0);
  if (camera.projection == Projection::Perspective) {
    const double ty = std::tan(camera.fovYDeg * std::numbers::pi / 360.0);
    proj[0][0] = 1.0 / (ty * aspect());
    proj[1][1] = 1.0 / ty;
    proj[2][2] = f / (n - f);  // depth 0 at near, 1 at far
    proj[2][3] = -1.0;
    proj[3][2] = n * f / (n - f);
  } else {
    const double halfH = camera.orthoHeight / 2, halfW = halfH * aspect();
    proj[0][0] = 1.0 / halfW;
    proj[1][1] = 1.0 / halfH;
    proj[2][2] = 1.0 / (n - f);
    proj[3][2] = n / (n - f);
    proj[3][3] = 1.0;
  }
  return proj * view;
}

CameraView cameraViewForFrame(const Scene& scene, int frame) {
  CameraView view;
  view.camera = scene.camera;
  view.width = scene.image.width;
  view.height = scene.image.height;
  const auto& path = scene.frames.cameraPath;
  if (path.size() >= 2) {
    // SPEC 2: t = f/(count-1); keyframe k sits at k/(m-1); linear in between.
    const int count = scene.frames.count;
    const double t = count > 1 ? double(std::clamp(frame, 0, count - 1)) / (count - 1) : 0.0;
    const double scaled = t * double(path.size() - 1);
    const std::size_t k = std::min(static_cast<std::size_t>(scaled), path.size() - 2);
    const double s = scaled - double(k);
    view.camera.position = glm::mix(path[k].position, path[k + 1].position, s);
    view.camera.target = glm::mix(path[k].target, path[k + 1].target, s);
  }
  view.forward = glm::normalize(view.camera.target - view.camera.position);
  view.right = glm::normalize(glm::cross(view.forward, view.camera.up));
  view.up = glm::cross(view.right, view.forward);
  return view;
}

}  // namespace lighting
