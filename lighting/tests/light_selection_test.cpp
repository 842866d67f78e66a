// SPEC 5.1-5.3 on small scenes whose answers are derived by hand in the
// comments. Scenes are built in code so the test does not depend on the loader.
#include "lighting/frame.h"
#include "lighting/tests/light_builders.h"

#include <gtest/gtest.h>

#include <cmath>

namespace lighting {
namespace {

using testing::directionalLight;
using testing::frameOf;
using testing::pointLight;

// The default camera of SPEC 2: orthographic, at (0, 10, 0) looking down with
// height 10 and a square image, so the frustum is |x| <= 5, |z| <= 5,
// -90 <= y <= 9.9.
Scene sceneWith(std::vector<Light> lights) {
  Scene s;
  s.lights = std::move(lights);
  Object floor;
  floor.mesh.planeSizeX = floor.mesh.planeSizeZ = 2;
  s.objects.push_back(floor);
  return s;
}


std::vector<std::pair<int, int>> visible(const Frame& f) {
  std::vector<std::pair<int, int>> out;
  for (const auto& v : f.selection.visible) out.emplace_back(v.light, v.packed);
  return out;
}

TEST(VisibleLights, OrderCullingAndTies) {
  std::vector<Light> lights = {
      pointLight({3, 0, 0}, 1),      // 0: distance^2 to camera 9 + 100 = 109
      pointLight({0, 0, 0}, 1),      // 1: 100
      directionalLight(0.5),         // 2: luminance 0.5
      directionalLight(1.0),         // 3: luminance 1
      pointLight({-3, 0, 0}, 1),     // 4: 109, ties with 0: lower index first
      pointLight({20, 0, 0}, 1),     // 5: 15 beyond the plane x = 5 with range 1: culled
      pointLight({5.5, 0, 0}, 1),    // 6: 0.5 beyond, range 1: visible; 30.25 + 100
      pointLight({0, 0, 0}, 1),      // 7: baked: no part
      directionalLight(0.5),         // 8: ties with 2
  };
  lights[7].mode = LightMode::Baked;
  const Frame f = frameOf(sceneWith(lights));
  const std::vector<std::pair<int, int>> expected = {{3, 0}, {2, 1}, {8, 2}, {1, 0}, {0, 1}, {4, 2}, {6, 3}};
  EXPECT_EQ(visible(f), expected);
  EXPECT_EQ(f.selection.packed.directional, (std::vector<int>{3, 2, 8}));
  EXPECT_EQ(f.selection.packed.other, (std::vector<int>{1, 0, 4, 6}));
}

TEST(VisibleLights, PerspectiveSidePlaneUsesTheRange) {
  // Camera at the origin looking down -Z, fov 90, square: the left plane is
  // x = z (z < 0) with inward normal (1, 0, -1)/sqrt2. (-10, 0, -5) lies
  // 5/sqrt2 = 3.5355 outside it.
  Scene s = sceneWith({pointLight({-10, 0, -5}, 3.5), pointLight({-10, 0, -5}, 3.6)});
  s.camera = Camera{{0, 0, 0}, {0, 0, -1}, {0, 1, 0}, Projection::Perspective, 90, 10, 0.1, 100};
  const Frame f = frameOf(s);
  EXPECT_EQ(visible(f), (std::vector<std::pair<int, int>>{{1, 0}}));
}

TEST(VisibleLights, SixtyFiveDropsTheFarthest) {
  std::vector<Light> lights;
  // Light k sits at (0, 0, 0.05 k): distance^2 to the camera 100 + (0.05 k)^2
  // grows with k, so light 64 is the 65th and the one dropped.
  for (int k = 0; k < 65; ++k) lights.push_back(pointLight({0, 0, 0.05 * k}, 1));
  const Frame f = frameOf(sceneWith(lights));
  ASSERT_EQ(f.selection.visible.size(), 65u);
  EXPECT_EQ(f.selection.packed.other.size(), 64u);
  EXPECT_EQ(f.selection.visible.back().light, 64);
  EXPECT_EQ(f.selection.visible.back().packed, -1);
  EXPECT_EQ(f.selection.visible[63].packed, 63);
}

TEST(VisibleLights, FiveDirectionalDropsTheDimmest) {
  const Frame f = frameOf(sceneWith({directionalLight(3), directionalLight(1), directionalLight(5),
                                     directionalLight(2), directionalLight(4)}));
  // Luminance order 5, 4, 3, 2, 1: lights 2, 4, 0, 3 kept, light 1 dropped.
  EXPECT_EQ(visible(f), (std::vector<std::pair<int, int>>{{2, 0}, {4, 1}, {0, 2}, {3, 3}, {1, -1}}));
}

TEST(VisibleLights, LegacySharesSixteenAcrossKinds) {
  std::vector<Light> lights = {directionalLight(1), directionalLight(2)};
  for (int k = 0; k < 16; ++k) lights.push_back(pointLight({0, 0, 0.1 * k}, 1));
  Scene s = sceneWith(lights);
  s.pipeline.profile = Profile::Legacy;
  const Frame f = frameOf(s);
  // Directional first (1 then 0), then points by distance: 14 of 16 fit.
  ASSERT_EQ(f.selection.packed.other.size(), 16u);
  EXPECT_TRUE(f.selection.packed.directional.empty());
  EXPECT_EQ(f.selection.packed.other[0], 1);
  EXPECT_EQ(f.selection.packed.other[1], 0);
  EXPECT_EQ(f.selection.packed.other[15], 15);  // point k = 13
  EXPECT_EQ(f.selection.visible[16].packed, -1);
  EXPECT_EQ(f.selection.visible[17].packed, -1);
}

// Eleven point lights on a ring of radius 2 around the floor's centre, in
// the floor's plane: all at the same distance from the camera (packed in scene
// order) and from the object, so importance follows intensity alone.
std::vector<Light> ringOfLights(const std::vector<double>& intensities) {
  std::vector<Light> lights;
  for (std::size_t k = 0; k < intensities.size(); ++k) {
    const double a = 2.0 * M_PI * double(k) / double(intensities.size());
    lights.push_back(pointLight({2 * std::cos(a), 0, 2 * std::sin(a)}, 10, intensities[k]));
  }
  return lights;
}

TEST(ObjectLightLists, ElevenLightsGiveCountElevenAndTheEightBrightest) {
  Scene s = sceneWith(ringOfLights({1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11}));
  s.pipeline.lightsPerObject = true;
  const Frame f = frameOf(s);
  ASSERT_EQ(f.objectLists.size(), 1u);
  EXPECT_EQ(f.objectLists[0].count, 11);
  EXPECT_EQ(f.objectLists[0].indices, (std::vector<int>{10, 9, 8, 7, 6, 5, 4, 3}));
}

TEST(ObjectLightLists, ImportanceTiesGoToTheLowerPackedIndex) {
  Scene s = sceneWith(ringOfLights({2, 5, 2, 5, 1}));
  s.pipeline.lightsPerObject = true;
  const Frame f = frameOf(s);
  EXPECT_EQ(f.objectLists[0].indices, (std::vector<int>{1, 3, 0, 2, 4}));
}

TEST(ObjectLightLists, LightsDroppedByTheBudgetNeverReachAList) {
  // 64 lights near the camera (y = 9) far from the floor (distance >= 9 >
  // range 1 + radius sqrt2), and one that touches the floor but is the 65th by
  // distance to the camera (9.5^2 = 90.25 against at most 1 + 32).
  std::vector<Light> lights;
  for (int k = 0; k < 64; ++k) lights.push_back(pointLight({-4 + (k % 8), 9, -4 + (k / 8)}, 1));
  lights.push_back(pointLight({0, 0.5, 0}, 2, 100));
  Scene s = sceneWith(lights);
  s.pipeline.lightsPerObject = true;
  const Frame f = frameOf(s);
  EXPECT_EQ(f.selection.visible.back().light, 64);
  EXPECT_EQ(f.selection.visible.back().packed, -1);
  EXPECT_EQ(f.objectLists[0].count, 0);
  EXPECT_TRUE(f.objectLists[0].indices.empty());
}

TEST(ObjectLightLists, LegacyPutsDirectionalLightsFirst) {
  std::vector<Light> lights = ringOfLights({1, 9});
  lights.push_back(directionalLight(0.1));
  Scene s = sceneWith(lights);
  s.pipeline.profile = Profile::Legacy;
  const Frame f = frameOf(s);
  // Packed: directional (light 2) at 0, then lights 0 and 1 at 1 and 2.
  EXPECT_EQ(f.selection.packed.other, (std::vector<int>{2, 0, 1}));
  EXPECT_EQ(f.objectLists[0].count, 3);
  EXPECT_EQ(f.objectLists[0].indices, (std::vector<int>{0, 2, 1}));
}

Light mixedShadowed(Light l, double strength = 1) {
  l.mode = LightMode::Mixed;
  l.shadows = true;
  l.shadowStrength = strength;
  return l;
}

TEST(ShadowMaskChannels, FourOverlappingThenOneDemotedAndAFarOneSharing) {
  std::vector<Light> lights = {
      mixedShadowed(pointLight({0, 0, 0}, 1, 1)),    // 0: weight 1
      mixedShadowed(pointLight({0, 0, 0}, 1, 4)),    // 1: weight 4
      mixedShadowed(pointLight({0, 0, 0}, 1, 3)),    // 2: 3
      mixedShadowed(pointLight({0, 0, 0}, 1, 2)),    // 3: 2
      mixedShadowed(pointLight({0, 0, 0}, 1, 0.5)),  // 4: 0.5, overlaps all four: demoted
      mixedShadowed(pointLight({3, 0, 0}, 1, 0.25)), // 5: |p| = 3 >= 1 + 1: overlaps none
      mixedShadowed(pointLight({0, 0, 0}, 1, 9), 0), // 6: strength 0: no candidate
      pointLight({0, 0, 0}, 1, 9),                   // 7: realtime: no candidate
  };
  const Frame f = frameOf(sceneWith(lights));
  const auto& e = f.prepared->shadowMask.entries;
  ASSERT_EQ(e.size(), 6u);
  const std::vector<std::tuple<int, int, bool>> expected = {{1, 0, false}, {2, 1, false}, {3, 2, false},
                                                            {0, 3, false}, {4, -1, true}, {5, 0, false}};
  for (std::size_t k = 0; k < e.size(); ++k)
    EXPECT_EQ(std::tuple(e[k].light, e[k].channel, e[k].demoted), expected[k]) << "entry " << k;
  // The demoted light is never lit in real time.
  for (const auto& v : f.selection.visible) EXPECT_NE(v.light, 4);
}

TEST(ShadowMaskChannels, DirectionalComesFirstAndOverlapsEverything) {
  Light sun = mixedShadowed(directionalLight(0.01));
  const Frame f = frameOf(sceneWith({mixedShadowed(pointLight({0, 0, 0}, 1, 5)), sun,
                                     mixedShadowed(pointLight({50, 0, 0}, 1, 5))}));
  const auto& e = f.prepared->shadowMask.entries;
  ASSERT_EQ(e.size(), 3u);
  EXPECT_EQ(std::tuple(e[0].light, e[0].channel), std::tuple(1, 0));
  // Equal weights: lower scene index first; both overlap only the sun.
  EXPECT_EQ(std::tuple(e[1].light, e[1].channel), std::tuple(0, 1));
  EXPECT_EQ(std::tuple(e[2].light, e[2].channel), std::tuple(2, 1));
}

TEST(AnimatedCamera, KeyframesInterpolateLinearly) {
  Scene s = sceneWith({});
  s.frames.count = 5;
  s.frames.cameraPath = {{{0, 10, 0}, {0, 0, 0}}, {{4, 10, 0}, {4, 0, 0}}, {{4, 10, 8}, {4, 0, 8}}};
  auto prepared = prepareScene(s);
  // Frame 1: t = 1/4, keyframe parameter 0.5: halfway from key 0 to key 1.
  EXPECT_EQ(prepareFrame(prepared, 1).view.camera.position, Vec3(2, 10, 0));
  // Frame 3: t = 3/4 -> 1.5: halfway from key 1 to key 2.
  EXPECT_EQ(prepareFrame(prepared, 3).view.camera.target, Vec3(4, 0, 4));
  EXPECT_EQ(prepareFrame(prepared, 4).view.camera.position, Vec3(4, 10, 8));
}

}  // namespace
}  // namespace lighting
