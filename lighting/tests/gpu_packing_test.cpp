// The std140 layout of the uniform blocks, offset by offset, against the rules
// of the GLSL spec (vec4 and ivec4 align to 16, mat4 is four vec4 columns,
// arrays of structs round each element up to 16), plus the camera-relative
// data and the hand-computed projection of one point.
#include "lighting/gpu_packing.h"

#include <gtest/gtest.h>

#include <cstddef>

namespace lighting {
namespace {

TEST(GpuPacking, Std140OffsetsOfTheLight) {
  EXPECT_EQ(offsetof(GpuLight, position), 0u);
  EXPECT_EQ(offsetof(GpuLight, color), 16u);
  EXPECT_EQ(offsetof(GpuLight, spotDirection), 32u);
  EXPECT_EQ(offsetof(GpuLight, spotAngles), 48u);
  EXPECT_EQ(sizeof(GpuLight), 64u);
}

TEST(GpuPacking, Std140OffsetsOfTheFrameBlock) {
  EXPECT_EQ(offsetof(GpuFrameBlock, viewProjection), 0u);
  EXPECT_EQ(offsetof(GpuFrameBlock, ambient), 64u);
  EXPECT_EQ(offsetof(GpuFrameBlock, lightCounts), 80u);
  EXPECT_EQ(offsetof(GpuFrameBlock, directionalLights), 96u);
  EXPECT_EQ(offsetof(GpuFrameBlock, otherLights), 96u + 4 * 64);
  EXPECT_EQ(offsetof(GpuFrameBlock, cameraPosition), 96u + 68 * 64);
  EXPECT_EQ(offsetof(GpuFrameBlock, view), 96u + 68 * 64 + 16);
  EXPECT_EQ(offsetof(GpuFrameBlock, clusterGrid), 96u + 68 * 64 + 32);
  EXPECT_EQ(offsetof(GpuFrameBlock, clusterScreen), 96u + 68 * 64 + 48);
  EXPECT_EQ(offsetof(GpuFrameBlock, clusterForward), 96u + 68 * 64 + 64);
  EXPECT_EQ(offsetof(GpuFrameBlock, clusterSlicing), 96u + 68 * 64 + 80);
  EXPECT_EQ(offsetof(GpuFrameBlock, opaqueZero), 96u + 68 * 64 + 96);
  EXPECT_EQ(offsetof(GpuFrameBlock, rasterGrid), 96u + 68 * 64 + 112);
  EXPECT_EQ(offsetof(GpuFrameBlock, filterGrid), 96u + 68 * 64 + 128);
  EXPECT_EQ(sizeof(GpuFrameBlock), 96u + 68 * 64 + 144);
}

// Three clusters listing {0, 2}, {}, {1}: headers at texels 0-2, the lists
// from texel 3 on; each header is (first texel << 8) | count.
TEST(GpuPacking, ClusterTexelsAreHeadersThenLists) {
  LightClusters clusters;
  clusters.first = {0, 2, 2};
  clusters.count = {2, 0, 1};
  clusters.lights = {0, 2, 1};
  const std::vector<std::uint32_t> texels = packClusterTexels(clusters);
  const std::vector<std::uint32_t> expected = {(3u << 8) | 2u, (5u << 8) | 0u, (5u << 8) | 1u, 0, 2, 1};
  EXPECT_EQ(texels, expected);
}

TEST(GpuPacking, Std140OffsetsOfTheObjectBlock) {
  EXPECT_EQ(offsetof(GpuObjectBlock, model), 0u);
  EXPECT_EQ(offsetof(GpuObjectBlock, normalMatrix), 64u);
  EXPECT_EQ(offsetof(GpuObjectBlock, albedo), 128u);
  EXPECT_EQ(offsetof(GpuObjectBlock, lightList), 144u);
  EXPECT_EQ(offsetof(GpuObjectBlock, lightIndices), 160u);
  EXPECT_EQ(offsetof(GpuObjectBlock, lightmapTransform), 192u);
  EXPECT_EQ(offsetof(GpuObjectBlock, material), 208u);
  EXPECT_EQ(offsetof(GpuObjectBlock, raster), 224u);
  EXPECT_EQ(sizeof(GpuObjectBlock), 240u);
}

Scene farPackingScene() {
  Scene s;
  const Vec3 far(1e6, 0, 1e6);
  s.camera.position = far + Vec3(0, 10, 0);
  s.camera.target = far;
  Object floor;
  floor.transform.translate = far;
  s.objects.push_back(floor);
  Light spot;
  spot.position = far + Vec3(1, 2, 3);
  spot.direction = {0, -1, 0};
  spot.spotAngleDeg = 90;
  spot.innerSpotAngleDeg = 0;
  spot.range = 2;
  s.lights.push_back(spot);
  return s;
}

TEST(GpuPacking, PositionsAreRelativeToTheCamera) {
  const Frame f = prepareFrame(prepareScene(farPackingScene()), 0);
  const GpuFrameBlock block = packFrameBlock(f);
  ASSERT_EQ(block.lightCounts.y, 1);
  const GpuLight& l = block.otherLights[0];
  // (1e6 + 1, 2, 1e6 + 3) - (1e6, 10, 1e6): small numbers, exact in float.
  EXPECT_EQ(l.position.x, 1.0f);
  EXPECT_EQ(l.position.y, -8.0f);
  EXPECT_EQ(l.position.z, 3.0f);
  EXPECT_EQ(l.position.w, 1.0f);
  EXPECT_EQ(l.color.w, 0.25f);  // 1 / range^2
  EXPECT_EQ(l.spotDirection.y, 1.0f);  // spotDir = -direction
  // Inner 0, outer 90: a = 2 + sqrt2, b = -(1 + sqrt2); no shadow-mask channel.
  EXPECT_FLOAT_EQ(l.spotAngles.x, 3.41421356f);
  EXPECT_FLOAT_EQ(l.spotAngles.y, -2.41421356f);
  EXPECT_EQ(l.spotAngles.z, -1.0f);
  // The camera position itself, only for the absolute-coordinates mutant.
  EXPECT_EQ(block.cameraPosition.x, 1e6f);
  EXPECT_EQ(block.cameraPosition.y, 10.0f);
  EXPECT_EQ(block.cameraPosition.z, 1e6f);
  const GpuObjectBlock object = packObjectBlock(f, 0);
  EXPECT_EQ(object.model.m[12], 0.0f);   // translate - camera = (0, -10, 0)
  EXPECT_EQ(object.model.m[13], -10.0f);
  EXPECT_EQ(object.model.m[14], 0.0f);
  EXPECT_EQ(object.lightList.x, 0);
  EXPECT_EQ(object.lightList.w, 0);  // no list in use: the full shader loops over every light
  EXPECT_EQ(block.lightCounts.z, 0);  // srp
  EXPECT_EQ(object.lightIndices[0].x, -1);
}

TEST(GpuPacking, ViewProjectionOfTheDefaultCamera) {
  // SPEC 2's default camera: orthographic at (0, 10, 0) looking down, up
  // (0, 0, -1), height 10, near 0.1, far 100. Right = forward x up = (1, 0, 0)
  // and screen up = (0, 0, -1); the world point (2.5, 0, -2.5) is 2.5 right and
  // 2.5 up of centre on a half-height of 5: NDC (0.5, 0.5), at view depth 10:
  // depth (10 - 0.1) / (100 - 0.1).
  Scene s;
  const Frame f = prepareFrame(prepareScene(s), 0);
  const GpuMat4 m = packFrameBlock(f).viewProjection;
  const double p[4] = {2.5, -10.0, -2.5, 1.0};  // camera-relative
  double clip[4] = {};
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) clip[r] += double(m.m[c * 4 + r]) * p[c];
  EXPECT_NEAR(clip[0] / clip[3], 0.5, 1e-6);
  EXPECT_NEAR(clip[1] / clip[3], 0.5, 1e-6);
  EXPECT_NEAR(clip[2] / clip[3], 9.9 / 99.9, 1e-6);
}

TEST(GpuPacking, ObjectListsAreMinusOnePastTheEnd) {
  Scene s;
  s.pipeline.lightsPerObject = true;
  Object floor;
  s.objects.push_back(floor);
  Light a, b;
  a.type = b.type = LightType::Point;
  a.position = {1, 1, 0};
  b.position = {-1, 1, 0};
  b.intensity = 5;
  s.lights = {a, b};
  const Frame f = prepareFrame(prepareScene(s), 0);
  const GpuObjectBlock block = packObjectBlock(f, 0);
  EXPECT_EQ(block.lightList.x, 2);
  EXPECT_EQ(block.lightList.w, 1);  // the list is in use
  // Equal camera distance: packed in scene order (a 0, b 1); b is brighter, so first.
  EXPECT_EQ(block.lightIndices[0].x, 1);
  EXPECT_EQ(block.lightIndices[0].y, 0);
  EXPECT_EQ(block.lightIndices[0].z, -1);
  EXPECT_EQ(block.lightIndices[1].w, -1);
}

}  // namespace
TEST(GpuPacking, LegacyProfileIsFlaggedForTheFullShader) {
  Scene s;
  s.pipeline.profile = Profile::Legacy;
  Object floor;
  s.objects.push_back(floor);
  Light a;
  a.type = LightType::Point;
  a.position = {1, 1, 0};
  s.lights = {a};
  const Frame f = prepareFrame(prepareScene(s), 0);
  EXPECT_EQ(packFrameBlock(f).lightCounts.z, 1);
  EXPECT_EQ(packObjectBlock(f, 0).lightList.w, 1);  // legacy always uses lists (SPEC 4)
}

}  // namespace lighting
