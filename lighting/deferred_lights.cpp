#include "lighting/deferred_lights.h"

#include "lighting/cookie_packing.h"
#include "lighting/shadow_packing.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

namespace lighting {
namespace {

// Each volume is made a little larger than the light's reach, so float
// rounding of its vertices (camera-relative, near the camera) and of the
// rasteriser never cut off a pixel the light touches. Too large costs only
// fragments that the light evaluates to exactly 0 (rangeAtt and spotAtt
// vanish outside range and cone).
constexpr double kVolumeSafetyFactor = 1.01;

// Icosahedron subdivided once: 80 faces.
constexpr int kIcosphereSubdivisions = 1;

struct Triangle {
  Vec3 a, b, c;
};

// A unit icosphere (vertices on the unit sphere) and its inscribed radius:
// the smallest distance from the centre to a face plane.
struct UnitIcosphere {
  std::vector<Triangle> triangles;
  double inscribedRadius = 0;
};

Vec3 unitNormal(const Triangle& t) { return glm::normalize(glm::cross(t.b - t.a, t.c - t.a)); }

// Counter-clockwise seen from outside: the face normal points away from an
// interior point of the convex volume.
Triangle facingOutward(const Triangle& t, const Vec3& interior) {
  const Vec3 n = glm::cross(t.b - t.a, t.c - t.a);
  if (glm::dot(n, t.a - interior) < 0) return {t.a, t.c, t.b};
  return t;
}

UnitIcosphere makeUnitIcosphere() {
  const double g = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Vec3> v = {{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0}, {0, -1, g}, {0, 1, g},
                         {0, -1, -g}, {0, 1, -g}, {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
  for (Vec3& p : v) p = glm::normalize(p);
  const int faces[20][3] = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                            {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                            {3, 8, 9},  {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  std::vector<Triangle> triangles;
  for (const auto& f : faces) triangles.push_back({v[f[0]], v[f[1]], v[f[2]]});
  for (int level = 0; level < kIcosphereSubdivisions; ++level) {
    std::vector<Triangle> finer;
    for (const Triangle& t : triangles) {
      const Vec3 ab = glm::normalize(t.a + t.b), bc = glm::normalize(t.b + t.c), ca = glm::normalize(t.c + t.a);
      finer.insert(finer.end(), {{t.a, ab, ca}, {ab, t.b, bc}, {ca, bc, t.c}, {ab, bc, ca}});
    }
    triangles = std::move(finer);
  }
  UnitIcosphere sphere;
  sphere.inscribedRadius = 1.0;
  for (Triangle& t : triangles) {
    t = facingOutward(t, Vec3(0.0));
    sphere.inscribedRadius = std::min(sphere.inscribedRadius, std::abs(glm::dot(unitNormal(t), t.a)));
  }
  sphere.triangles = std::move(triangles);
  return sphere;
}

const UnitIcosphere& unitIcosphere() {
  static const UnitIcosphere sphere = makeUnitIcosphere();
  return sphere;
}

// Camera-relative in double, then the one rounding to float.
void appendTriangle(std::vector<GpuVec4>& out, const Triangle& t, const Vec3& camera) {
  for (const Vec3& p : {t.a, t.b, t.c}) {
    const Vec3 r = p - camera;
    out.push_back({float(r.x), float(r.y), float(r.z), 1.0f});
  }
}

std::vector<Triangle> icosphere(const Vec3& centre, double range) {
  const UnitIcosphere& unit = unitIcosphere();
  const double scale = range * kVolumeSafetyFactor / unit.inscribedRadius;
  std::vector<Triangle> out;
  out.reserve(unit.triangles.size());
  for (const Triangle& t : unit.triangles) out.push_back({centre + t.a * scale, centre + t.b * scale, centre + t.c * scale});
  return out;
}

// Apex at the light, axis along its direction, as long as the range; at
// every distance t along the axis the square cross-section's inscribed circle
// has radius above t * tan(outer half angle), so it holds the cone's circle.
std::vector<Triangle> pyramid(const Vec3& apex, const Vec3& direction, double range, double outerHalfAngleRad) {
  const Vec3 axis = glm::normalize(direction);
  const Vec3 helper = std::abs(axis.y) < 0.9 ? Vec3(0, 1, 0) : Vec3(1, 0, 0);
  const Vec3 u = glm::normalize(glm::cross(axis, helper));
  const Vec3 v = glm::cross(axis, u);
  const double length = range * kVolumeSafetyFactor;
  // The sides' slope sets the margin around the cone, so the factor applies
  // to it again (scaling the base and the length alike would leave the slope
  // exactly tan(outer half angle), with the cone's rim on the side planes).
  const double halfWidth = length * std::tan(outerHalfAngleRad) * kVolumeSafetyFactor;
  const Vec3 baseCentre = apex + axis * length;
  const std::array<Vec3, 4> corners = {baseCentre + (u + v) * halfWidth, baseCentre + (-u + v) * halfWidth,
                                       baseCentre + (-u - v) * halfWidth, baseCentre + (u - v) * halfWidth};
  const Vec3 interior = apex + axis * (0.75 * length);
  std::vector<Triangle> out;
  for (int i = 0; i < 4; ++i) out.push_back(facingOutward({apex, corners[i], corners[(i + 1) % 4]}, interior));
  out.push_back(facingOutward({corners[0], corners[1], corners[2]}, interior));
  out.push_back(facingOutward({corners[0], corners[2], corners[3]}, interior));
  return out;
}

// Clip space, w = 1: (-1,-1), (3,-1), (-1,3) covers [-1, 1]^2; counter-
// clockwise with y up. Depth 0.5, inside the clip volume (the pass tests ALWAYS).
std::vector<GpuVec4> fullScreenTriangle() {
  return {{-1, -1, 0.5f, 1}, {3, -1, 0.5f, 1}, {-1, 3, 0.5f, 1}};
}

// The kept lights in packed order with their fade weights.
std::vector<std::pair<int, double>> keptLights(const Frame& frame) {
  const PackedLights& packed = frame.selection.packed;
  std::vector<std::pair<int, double>> lights;
  for (std::size_t i = 0; i < packed.directional.size(); ++i)
    lights.emplace_back(packed.directional[i], packed.directionalWeight[i]);
  for (std::size_t i = 0; i < packed.other.size(); ++i) lights.emplace_back(packed.other[i], packed.otherWeight[i]);
  return lights;
}

}  // namespace

LightVolume lightVolume(const Frame& frame, int sceneLight) {
  const Light& light = frame.scene().lights[sceneLight];
  const Vec3& camera = frame.view.camera.position;
  LightVolume volume;
  volume.light = sceneLight;
  volume.slots = {cookieBlockSlot(frame, sceneLight), shadowBlockSlot(frame, sceneLight)};
  std::vector<Triangle> triangles;
  const double outerHalfAngleDeg = light.spotAngleDeg / 2.0;
  if (light.type == LightType::Directional) {
    volume.shape = LightVolumeShape::FullScreen;
    volume.vertices = fullScreenTriangle();
    return volume;
  }
  if (light.type == LightType::Spot && outerHalfAngleDeg < kWidestPyramidHalfAngleDeg) {
    volume.shape = LightVolumeShape::Pyramid;
    triangles = pyramid(light.position, light.direction, light.range, outerHalfAngleDeg * std::numbers::pi / 180.0);
  } else {
    volume.shape = LightVolumeShape::Icosphere;
    triangles = icosphere(light.position, light.range);
  }
  for (const Triangle& t : triangles) appendTriangle(volume.vertices, t, camera);
  return volume;
}

std::vector<LightVolume> lightVolumes(const Frame& frame) {
  std::vector<LightVolume> volumes;
  for (const auto& [light, weight] : keptLights(frame)) volumes.push_back(lightVolume(frame, light));
  return volumes;
}

GpuDeferredLightBlock packDeferredLight(const Frame& frame, int sceneLight) {
  for (const auto& [light, weight] : keptLights(frame)) {
    if (light != sceneLight) continue;
    GpuDeferredLightBlock block;
    block.light = packGpuLight(frame, light, weight);
    const bool directional = frame.scene().lights[light].type == LightType::Directional;
    block.info = {directional ? 1 : 0, directional ? 1 : 0, 0, 0};
    return block;
  }
  throw std::logic_error("packDeferredLight: light " + std::to_string(sceneLight) + " is not kept in this frame");
}

GpuDeferredFrameBlock packDeferredFrame(const Frame& frame) {
  GpuDeferredFrameBlock block;
  block.inverseViewProjection = toGpuMat4(glm::inverse(frame.view.cameraRelativeViewProjection()));
  const DeferredBuffer buffer = frame.scene().pipeline.deferredBuffer;
  block.buffer = {buffer == DeferredBuffer::Hdr32 ? 0 : buffer == DeferredBuffer::Hdr16 ? 1 : 2, 0, 0, 0};
  return block;
}

RasterState lightVolumeRasterState(LightVolumeShape shape, VolumeRule rule) {
  constexpr bool kNoDepthWrites = false;
  switch (shape) {
    case LightVolumeShape::FullScreen: return {CullMode::None, DepthCompare::Always, kNoDepthWrites, false};
    case LightVolumeShape::Icosphere:
      if (rule == VolumeRule::OutsideOnlyMutant)
        return {CullMode::Back, DepthCompare::LessOrEqual, kNoDepthWrites, true};
      break;
    case LightVolumeShape::Pyramid: break;
  }
  return {CullMode::Front, DepthCompare::GreaterOrEqual, kNoDepthWrites, true};
}

LightBufferState lightBufferState(DeferredBuffer buffer) {
  if (buffer == DeferredBuffer::Ldr8) return {LightBlend::Multiply, 1.0f};
  return {LightBlend::Add, 0.0f};
}

}  // namespace lighting
