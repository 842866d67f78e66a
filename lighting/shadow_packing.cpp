#include "lighting/shadow_packing.h"

namespace lighting {
namespace {

GpuShadow packShadow(const Frame& frame, const ShadowProjection& projection) {
  const Light& light = frame.scene().lights[projection.light];
  const Vec3 camera = frame.view.camera.position;
  GpuShadow g;
  const bool cube = projection.type == LightType::Point;
  const GpuShadowKind kind = cube                                           ? GpuShadowKind::Cube
                             : projection.type == LightType::Directional ? GpuShadowKind::Orthographic
                                                                         : GpuShadowKind::Perspective;
  g.clipFromCameraRelative = toGpuMat4(projection.views[0].clipFromCameraRelative(camera));
  g.params = {float(int(kind)), float(int(projection.spec.filter)), float(projection.spec.resolution),
              float(light.shadowStrength)};
  double a = 0, b = 0;
  if (cube) {
    const ShadowView& view = projection.views[0];
    a = view.farPlane / (view.farPlane - view.nearPlane);
    b = a * view.nearPlane;
  }
  g.bias = {float(projection.spec.depthBias), float(projection.spec.normalBias), float(a), float(b)};
  if (projection.type == LightType::Directional) {
    const Vec3 toLight = -light.direction;
    g.light = {float(toLight.x), float(toLight.y), float(toLight.z), 0.0f};
  } else {
    const Vec3 p = light.position - camera;
    g.light = {float(p.x), float(p.y), float(p.z), 1.0f};
  }
  return g;
}

}  // namespace

GpuShadowBlock packShadowBlock(const Frame& frame) {
  GpuShadowBlock block;
  const ShadowSlots& slots = frame.shadows;
  for (int s = 0; s < int(slots.maps.size()); ++s) block.shadows[s] = packShadow(frame, slots.maps[s]);
  for (int s = 0; s < int(slots.cubes.size()); ++s)
    block.shadows[kMaxShadowMaps + s] = packShadow(frame, slots.cubes[s]);
  const Vec3 forward = frame.view.forward;
  block.fade = {float(forward.x), float(forward.y), float(forward.z), float(frame.scene().pipeline.shadowDistance)};
  return block;
}

int shadowBlockSlot(const Frame& frame, int sceneLight) {
  if (sceneLight >= int(frame.shadows.slotOfLight.size())) return -1;
  const int slot = frame.shadows.slotOfLight[sceneLight];
  if (slot < 0) return -1;
  return frame.scene().lights[sceneLight].type == LightType::Point ? kMaxShadowMaps + slot : slot;
}

std::vector<ShadowPassView> shadowPassViews(const Frame& frame) {
  std::vector<ShadowPassView> views;
  const Vec3 camera = frame.view.camera.position;
  auto add = [&](const ShadowProjection& projection, int slot) {
    for (int face = 0; face < int(projection.views.size()); ++face)
      views.push_back({slot, face, projection.spec.resolution,
                       toGpuMat4(projection.views[face].clipFromCameraRelative(camera)),
                       !projection.views[face].perspective});
  };
  for (int s = 0; s < int(frame.shadows.maps.size()); ++s) add(frame.shadows.maps[s], s);
  for (int s = 0; s < int(frame.shadows.cubes.size()); ++s) add(frame.shadows.cubes[s], kMaxShadowMaps + s);
  return views;
}

GpuShadowPassBlock packShadowPassBlock(const ShadowPassView& view, int subPixelBits) {
  const float size = float(view.resolution);
  return {view.clipFromCameraRelative,
          {size, size, view.snappable ? std::ldexp(1.0f, subPixelBits) : 0.0f, 1.0f}};
}

}  // namespace lighting
