// The deferred path's light volumes (SPEC 3.7), checked with facts derived by
// hand, not by the code under test: every point the light reaches (the sphere
// of radius range; the cone out to range) lies inside every face plane of its
// volume, every face is wound counter-clockwise seen from outside, and the
// directional triangle covers clip [-1, 1]^2.
#include "lighting/deferred_lights.h"
#include "lighting/tests/light_builders.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace lighting {
namespace {

using testing::directionalLight;

// Far from the origin, so the camera-relative subtraction matters (SPEC 7).
const Vec3 kFar(1e5, 0, -2e5);

Light deferredPointLight(const Vec3& position, double range) {
  Light l;
  l.type = LightType::Point;
  l.position = position;
  l.range = range;
  return l;
}

Light spotLight(const Vec3& position, const Vec3& direction, double range, double fullAngleDeg) {
  Light l;
  l.type = LightType::Spot;
  l.position = position;
  l.direction = glm::normalize(direction);
  l.range = range;
  l.spotAngleDeg = fullAngleDeg;
  return l;
}

// A perspective camera looking at kFar with every light in view.
Frame frameWith(std::vector<Light> lights, Profile profile = Profile::Srp) {
  Scene s;
  s.camera.position = kFar + Vec3(0, 6, 8);
  s.camera.target = kFar;
  s.camera.up = {0, 1, 0};
  s.camera.projection = Projection::Perspective;
  s.camera.fovYDeg = 90;
  s.pipeline.path = RenderPath::Deferred;
  s.pipeline.profile = profile;
  s.lights = std::move(lights);
  return prepareFrame(prepareScene(std::move(s)), 0);
}

struct Face {
  Vec3 a, normal;  // normal = (b - a) x (c - a): outward for counter-clockwise seen from outside
};

// Back to world space in double: vertex (float, camera-relative) + camera.
std::vector<Face> facesOf(const LightVolume& v, const Vec3& camera) {
  std::vector<Face> faces;
  auto world = [&](const GpuVec4& p) { return Vec3(p.x, p.y, p.z) + camera; };
  for (std::size_t i = 0; i + 2 < v.vertices.size(); i += 3) {
    const Vec3 a = world(v.vertices[i]), b = world(v.vertices[i + 1]), c = world(v.vertices[i + 2]);
    faces.push_back({a, glm::cross(b - a, c - a)});
  }
  return faces;
}

// Inside (or on) the convex volume: behind every face plane.
bool inside(const std::vector<Face>& faces, const Vec3& p) {
  for (const Face& f : faces)
    if (glm::dot(glm::normalize(f.normal), p - f.a) > 0) return false;
  return true;
}

// Near-uniform directions on the unit sphere (a Fibonacci spiral).
std::vector<Vec3> sphereDirections(int count) {
  std::vector<Vec3> out;
  const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < count; ++i) {
    const double y = 1.0 - 2.0 * (i + 0.5) / count;
    const double r = std::sqrt(1.0 - y * y);
    out.push_back({r * std::cos(golden * i), y, r * std::sin(golden * i)});
  }
  return out;
}

TEST(DeferredLights, PointVolumeIsAnIcosphereHoldingTheRangeSphere) {
  const Vec3 centre = kFar + Vec3(1, 0.5, -2);
  const double range = 3;
  const Frame frame = frameWith({deferredPointLight(centre, range)});
  const std::vector<LightVolume> volumes = lightVolumes(frame);
  ASSERT_EQ(volumes.size(), 1u);
  EXPECT_EQ(volumes[0].light, 0);
  EXPECT_EQ(volumes[0].shape, LightVolumeShape::Icosphere);
  // An icosahedron subdivided once: 80 triangles; at most a few hundred vertices.
  EXPECT_EQ(volumes[0].vertices.size() % 3, 0u);
  EXPECT_GE(volumes[0].vertices.size(), 3u * 80);
  const std::vector<Face> faces = facesOf(volumes[0], frame.view.camera.position);
  for (const Vec3& d : sphereDirections(4000)) ASSERT_TRUE(inside(faces, centre + d * range)) << d.x << " " << d.y << " " << d.z;
  // Outward winding: each face's normal points away from the centre.
  for (const Face& f : faces) EXPECT_GT(glm::dot(f.normal, f.a - centre), 0.0);
  // Not absurdly large: the circumscribed radius is below 1.5 range.
  for (const GpuVec4& p : volumes[0].vertices)
    EXPECT_LT(glm::length(Vec3(p.x, p.y, p.z) + frame.view.camera.position - centre), 1.5 * range);
}

TEST(DeferredLights, SpotVolumeIsAPyramidHoldingTheCone) {
  const Vec3 apex = kFar + Vec3(0, 4, 0);
  const Vec3 direction = glm::normalize(Vec3(0.3, -1, 0.2));
  const double range = 5, fullAngle = 70;
  const Frame frame = frameWith({spotLight(apex, direction, range, fullAngle)});
  const std::vector<LightVolume> volumes = lightVolumes(frame);
  ASSERT_EQ(volumes.size(), 1u);
  EXPECT_EQ(volumes[0].shape, LightVolumeShape::Pyramid);
  EXPECT_EQ(volumes[0].vertices.size(), 3u * 6);  // four sides, two base triangles
  const std::vector<Face> faces = facesOf(volumes[0], frame.view.camera.position);
  // The cone: angle to the axis at most the outer half angle, distance at most range.
  const double half = glm::radians(fullAngle / 2);
  for (const Vec3& d : sphereDirections(4000)) {
    if (glm::dot(d, direction) < std::cos(half)) continue;
    for (double t : {0.25, 0.5, 1.0}) ASSERT_TRUE(inside(faces, apex + d * (range * t)));
  }
  // The rim of the cap: exactly at the outer angle and the range.
  const Vec3 u = glm::normalize(glm::cross(direction, Vec3(1, 0, 0)));
  const Vec3 v = glm::cross(direction, u);
  for (int k = 0; k < 360; ++k) {
    const double phi = glm::radians(double(k));
    const Vec3 rim = direction * std::cos(half) + (u * std::cos(phi) + v * std::sin(phi)) * std::sin(half);
    ASSERT_TRUE(inside(faces, apex + rim * range)) << k;
  }
  const Vec3 interior = apex + direction * (0.5 * range);
  for (const Face& f : faces) EXPECT_GT(glm::dot(f.normal, f.a - interior), 0.0);
  // Points clearly behind the light are outside.
  EXPECT_FALSE(inside(faces, apex - direction * 0.5));
}

TEST(DeferredLights, WideSpotGetsAnIcosphere) {
  // Full angle 160: half angle 80 >= kWidestPyramidHalfAngleDeg (75).
  const Vec3 position = kFar + Vec3(0, 3, 0);
  const Frame frame = frameWith({spotLight(position, {0, -1, 0}, 2, 160)});
  const std::vector<LightVolume> volumes = lightVolumes(frame);
  ASSERT_EQ(volumes.size(), 1u);
  EXPECT_EQ(volumes[0].shape, LightVolumeShape::Icosphere);
  const std::vector<Face> faces = facesOf(volumes[0], frame.view.camera.position);
  for (const Vec3& d : sphereDirections(2000)) ASSERT_TRUE(inside(faces, position + d * 2.0));
  // Just below the limit (half angle 74) is still a pyramid.
  EXPECT_EQ(lightVolumes(frameWith({spotLight(position, {0, -1, 0}, 2, 148)}))[0].shape, LightVolumeShape::Pyramid);
}

// Barycentric test in 2D: p inside (or on) triangle abc.
bool insideTriangle2d(const GpuVec4& a, const GpuVec4& b, const GpuVec4& c, double x, double y) {
  auto edge = [](const GpuVec4& p, const GpuVec4& q, double x, double y) {
    return (double(q.x) - p.x) * (y - p.y) - (double(q.y) - p.y) * (x - p.x);
  };
  return edge(a, b, x, y) >= 0 && edge(b, c, x, y) >= 0 && edge(c, a, x, y) >= 0;
}

TEST(DeferredLights, DirectionalVolumeIsAFullScreenTriangle) {
  const Frame frame = frameWith({deferredPointLight(kFar, 1), directionalLight()});
  const std::vector<LightVolume> volumes = lightVolumes(frame);
  ASSERT_EQ(volumes.size(), 2u);
  // Packed order: directional first.
  EXPECT_EQ(volumes[0].light, 1);
  EXPECT_EQ(volumes[1].light, 0);
  const LightVolume& v = volumes[0];
  EXPECT_EQ(v.shape, LightVolumeShape::FullScreen);
  ASSERT_EQ(v.vertices.size(), 3u);
  for (const GpuVec4& p : v.vertices) {
    EXPECT_EQ(p.w, 1.0f);
    EXPECT_GE(p.z, 0.0f);  // inside Vulkan's clip depth 0..w
    EXPECT_LE(p.z, 1.0f);
  }
  // Counter-clockwise with y up, and every point of [-1, 1]^2 (corners included) covered.
  for (int i = 0; i <= 20; ++i)
    for (int j = 0; j <= 20; ++j)
      EXPECT_TRUE(insideTriangle2d(v.vertices[0], v.vertices[1], v.vertices[2], -1 + i * 0.1, -1 + j * 0.1)) << i << "," << j;
}

TEST(DeferredLights, LightBlockCarriesTheKindAndTheCameraRelativePosition) {
  const Vec3 position = kFar + Vec3(1, 2, 3);
  const Frame frame = frameWith({deferredPointLight(position, 4), directionalLight()});
  const GpuDeferredLightBlock point = packDeferredLight(frame, 0);
  EXPECT_EQ(point.info.x, 0);
  EXPECT_EQ(point.info.y, 0);
  // Camera at kFar + (0, 6, 8): the light is (1, -4, -5) from it.
  EXPECT_EQ(point.light.position.x, 1.0f);
  EXPECT_EQ(point.light.position.y, -4.0f);
  EXPECT_EQ(point.light.position.z, -5.0f);
  EXPECT_EQ(point.light.position.w, 1.0f);
  EXPECT_FLOAT_EQ(point.light.color.w, 1.0f / 16.0f);  // invRangeSq
  const GpuDeferredLightBlock sun = packDeferredLight(frame, 1);
  EXPECT_EQ(sun.info.x, 1);
  EXPECT_EQ(sun.info.y, 1);
  EXPECT_EQ(sun.light.position.y, 1.0f);  // L = -direction
  EXPECT_EQ(sun.light.position.w, 0.0f);
}

TEST(DeferredLights, LightBlockRefusesALightThatIsNotKept) {
  // Range 1 at 1000 units behind the camera: outside the frustum, not kept.
  const Frame frame = frameWith({deferredPointLight(kFar + Vec3(0, 6, 1008), 1)});
  EXPECT_TRUE(lightVolumes(frame).empty());
  EXPECT_THROW(packDeferredLight(frame, 0), std::logic_error);
}

TEST(DeferredLights, FrameBlockUnprojectsClipToCameraRelativeWorld) {
  Frame frame = frameWith({directionalLight()});
  const GpuDeferredFrameBlock block = packDeferredFrame(frame);
  EXPECT_EQ(block.buffer.x, 0);
  glm::dmat4 inverse;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) inverse[c][r] = block.inverseViewProjection.m[c * 4 + r];
  // The point the camera looks at (kFar) is straight ahead: clip x = y = 0.
  // Camera-relative it is (0, -6, -8), distance 10 along the view axis.
  const glm::dvec4 clip = frame.view.cameraRelativeViewProjection() * glm::dvec4(0, -6, -8, 1);
  EXPECT_NEAR(clip.x / clip.w, 0.0, 1e-12);
  EXPECT_NEAR(clip.y / clip.w, 0.0, 1e-12);
  const glm::dvec4 back = inverse * (clip / clip.w);
  EXPECT_NEAR(back.x / back.w, 0.0, 1e-4);
  EXPECT_NEAR(back.y / back.w, -6.0, 1e-4);
  EXPECT_NEAR(back.z / back.w, -8.0, 1e-4);
}

TEST(DeferredLights, FrameBlockNamesTheBuffer) {
  for (auto [buffer, code] : {std::pair{DeferredBuffer::Hdr32, 0}, {DeferredBuffer::Hdr16, 1}, {DeferredBuffer::Ldr8, 2}}) {
    Scene s;
    s.pipeline.path = RenderPath::Deferred;
    s.pipeline.deferredBuffer = buffer;
    const Frame frame = prepareFrame(prepareScene(s), 0);
    EXPECT_EQ(packDeferredFrame(frame).buffer.x, code);
    EXPECT_EQ(frame.features.ldr8Buffer, buffer == DeferredBuffer::Ldr8);
  }
}

TEST(DeferredLights, DeferredFrameLightsEveryKeptLightPerPixel) {
  // lights_per_object and the legacy profile do not apply to deferred: no
  // lists, no vertex lights, every kept light per pixel.
  std::vector<Light> lights;
  for (int i = 0; i < 10; ++i) lights.push_back(deferredPointLight(kFar + Vec3(i * 0.1, 0, 0), 2));
  for (Profile profile : {Profile::Srp, Profile::Legacy}) {
    Scene s;
    s.camera.position = kFar + Vec3(0, 10, 0);
    s.camera.target = kFar;
    s.pipeline.path = RenderPath::Deferred;
    s.pipeline.profile = profile;
    s.pipeline.lightsPerObject = true;
    s.lights = lights;
    s.objects.push_back(Object{});
    s.objects.back().transform.translate = kFar;
    const Frame frame = prepareFrame(prepareScene(s), 0);
    EXPECT_TRUE(frame.objectLists.empty());
    EXPECT_FALSE(frame.features.perObjectLists);
    EXPECT_FALSE(frame.features.vertexLights);
    const ObjectLights lit = frame.lightsForObject(0);
    EXPECT_TRUE(lit.perVertex.empty());
    // srp keeps all 10 (limit 64); legacy keeps 10 too (limit 16).
    EXPECT_EQ(lit.perPixel.size(), 10u);
  }
}

}  // namespace
}  // namespace lighting
