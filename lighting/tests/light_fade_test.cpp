// Fading the last kept lights (lighting/light_fade.h, docs/model.md): the
// weight rule on hand-picked numbers, then the selection on lights on a line
// whose squared distances are exact binary fractions, so every expected weight
// is a ratio of small integers derived in the comments.
#include "lighting/gpu_packing.h"
#include "lighting/light_fade.h"
#include "lighting/selection_json.h"
#include "lighting/tests/light_builders.h"

#include <gtest/gtest.h>

namespace lighting {
namespace {

using testing::directionalLight;
using testing::frameOf;
using testing::pointLight;

TEST(FadeWeight, LinearInSquaredDistanceBetweenStartAndCut) {
  EXPECT_EQ(fadeWeight(5, 4, 8), 0.75);  // (8 - 5) / (8 - 4)
  EXPECT_EQ(fadeWeight(4, 4, 8), 1.0);   // at the start
  EXPECT_EQ(fadeWeight(1, 4, 8), 1.0);   // nearer than the start
  EXPECT_EQ(fadeWeight(8, 4, 8), 0.0);   // at the cut
}

TEST(FadeWeight, EqualStartAndCutNeverDivideByZero) {
  // A kept light tied with the first dropped one gets its 0; nearer ones 1.
  EXPECT_EQ(fadeWeight(8, 8, 8), 0.0);
  EXPECT_EQ(fadeWeight(7, 8, 8), 1.0);
}

TEST(FadeWeights, TheLastNKeptLightsFade) {
  const std::vector<double> kept = {1, 4, 9, 16};
  // N = 2: start is kept[4 - 2 - 1] = 4, cut 25: (25 - 9) / 21, (25 - 16) / 21.
  EXPECT_EQ(fadeWeights(kept, 25.0, 2), (std::vector<double>{1, 1, 16.0 / 21, 9.0 / 21}));
  // N = 3: start 1: 21/24, 16/24, 9/24.
  EXPECT_EQ(fadeWeights(kept, 25.0, 3), (std::vector<double>{1, 21.0 / 24, 16.0 / 24, 9.0 / 24}));
  // N = every kept light: start is the camera itself, 0.
  EXPECT_EQ(fadeWeights(kept, 25.0, 4), (std::vector<double>{24.0 / 25, 21.0 / 25, 16.0 / 25, 9.0 / 25}));
  // N larger than the kept count: the same.
  EXPECT_EQ(fadeWeights(kept, 25.0, 9), fadeWeights(kept, 25.0, 4));
}

TEST(FadeWeights, NothingFadesWithoutADroppedLightOrWithNZero) {
  const std::vector<double> kept = {1, 4, 9, 16};
  EXPECT_EQ(fadeWeights(kept, std::nullopt, 2), (std::vector<double>{1, 1, 1, 1}));
  EXPECT_EQ(fadeWeights(kept, 25.0, 0), (std::vector<double>{1, 1, 1, 1}));
  EXPECT_TRUE(fadeWeights({}, 25.0, 2).empty());
}

// SPEC 2's default camera (orthographic, at (0, 10, 0) looking down, height
// 10): light k at (0, 9 - k/8, 0) sits d = 1 + k/8 = (8 + k)/8 below it, so
// d^2 = (8 + k)^2 / 64 exactly; the frustum holds y <= 9.9 and |x|, |z| <= 5.
Scene lineOfLights(int count, int fade, Profile profile = Profile::Srp) {
  Scene s;
  s.pipeline.profile = profile;
  s.pipeline.fadeLastLights = fade;
  for (int k = 0; k < count; ++k) s.lights.push_back(pointLight({0, 9 - k / 8.0, 0}));
  Object floor;
  floor.mesh.planeSizeX = floor.mesh.planeSizeZ = 2;
  s.objects.push_back(floor);
  return s;
}


TEST(FadeSelection, SixtyFiveOnALineFadeTheLastEight) {
  // Kept k = 0..63, cut at k = 64: d = 9, d^2 = 81 = 5184/64. N = 8: start is
  // rank 64 - 8 - 1 = 55, d^2 = 63^2/64 = 3969/64. Weight of k in 56..63:
  // (5184 - (8 + k)^2) / (5184 - 3969) = (5184 - (8 + k)^2) / 1215.
  const Frame f = frameOf(lineOfLights(65, 8));
  ASSERT_EQ(f.selection.visible.size(), 65u);
  ASSERT_EQ(f.selection.packed.otherWeight.size(), 64u);
  for (int k = 0; k < 65; ++k) {
    const VisibleLight& v = f.selection.visible[k];
    ASSERT_EQ(v.light, k);
    double expected = 1;
    if (k >= 56) expected = (5184.0 - (8.0 + k) * (8.0 + k)) / 1215.0;
    if (k == 64) expected = 0;  // dropped
    EXPECT_EQ(v.weight, expected) << "light " << k;
    if (k < 64) {
      EXPECT_EQ(f.selection.packed.otherWeight[k], expected) << "light " << k;
    }
  }
  EXPECT_EQ(f.selection.visible[63].weight, 143.0 / 1215.0);  // 5184 - 71^2
  EXPECT_EQ(f.selection.visible[56].weight, 1088.0 / 1215.0);  // 5184 - 64^2
}

TEST(FadeSelection, NoFadeWithoutTheKeyOrWithoutADroppedLight) {
  for (const Frame& f : {frameOf(lineOfLights(65, 0)), frameOf(lineOfLights(64, 8))}) {
    for (int k = 0; k < 64; ++k) EXPECT_EQ(f.selection.visible[k].weight, 1.0);
    for (double w : f.selection.packed.otherWeight) EXPECT_EQ(w, 1.0);
  }
}

TEST(FadeSelection, DirectionalLightsNeverFade) {
  Scene s = lineOfLights(65, 64);
  s.lights.push_back(directionalLight(1));
  const Frame f = frameOf(s);
  ASSERT_EQ(f.selection.packed.directionalWeight, std::vector<double>{1.0});
  // N = 64: start is the camera, 0: weight (5184 - (8 + k)^2) / 5184 for all.
  EXPECT_EQ(f.selection.packed.otherWeight[0], (5184.0 - 64.0) / 5184.0);
  EXPECT_EQ(f.selection.packed.otherWeight[63], (5184.0 - 71.0 * 71.0) / 5184.0);
}

TEST(FadeSelection, LegacyFadesThePointLightsLeftAfterTheDirectionalOnes) {
  // Two directional lights take packed 0 and 1; points k = 0..13 are kept,
  // k = 14 (d^2 = 22^2/64 = 484/64) is the cut. N = 4: start is kept point
  // rank 14 - 4 - 1 = 9, d^2 = 17^2/64 = 289/64: weight (484 - (8 + k)^2) / 195.
  Scene s = lineOfLights(16, 4, Profile::Legacy);
  s.lights.push_back(directionalLight(1));
  s.lights.push_back(directionalLight(2));
  const Frame f = frameOf(s);
  const std::vector<double>& w = f.selection.packed.otherWeight;
  ASSERT_EQ(w.size(), 16u);
  EXPECT_EQ(w[0], 1.0);
  EXPECT_EQ(w[1], 1.0);
  for (int k = 0; k < 14; ++k) {
    const double expected = k >= 10 ? (484.0 - (8.0 + k) * (8.0 + k)) / 195.0 : 1.0;
    EXPECT_EQ(w[2 + k], expected) << "point " << k;
  }
  EXPECT_EQ(w[15], 43.0 / 195.0);
}

TEST(FadeSelection, AWeightGoesToZeroAsItsLightCrossesTheCut) {
  // 63 lights on the line (k = 0..62) and A = (2, 1, 0), B = (-2, 1, 0), 65 in
  // all, with the camera moved by e along x. At e = 1/64: A is the 64th,
  // d_A^2 = (127/64)^2 + 81 and B the cut, d_B^2 = (129/64)^2 + 81, their
  // difference 512/4096 = 1/8; start (rank 55) d^2 = e^2 + 3969/64, so
  // cut - start = 16640/4096 + 1215/64 = 23.046875 and A's weight is
  // 0.125 / 23.046875. At e = -1/64, B has it; at e = 0 they tie and the kept
  // one (A, the lower index) has the dropped one's 0: no jump either way.
  auto weights = [](double e) {
    Scene s = lineOfLights(63, 8);
    s.lights.push_back(pointLight({2, 1, 0}));
    s.lights.push_back(pointLight({-2, 1, 0}));
    s.camera.position.x = s.camera.target.x = e;
    const std::vector<double> w = frameOf(s).selection.weightsBySceneLight(65);
    return std::pair(w[63], w[64]);
  };
  EXPECT_EQ(weights(1.0 / 64), std::pair(0.125 / 23.046875, 0.0));
  EXPECT_EQ(weights(0), std::pair(0.0, 0.0));
  EXPECT_EQ(weights(-1.0 / 64), std::pair(0.0, 0.125 / 23.046875));
}

TEST(FadeSelection, PackedColourIsFinalColourTimesTheWeight) {
  Scene s = lineOfLights(65, 8);
  s.lights[63].color = {1, 0.5, 0.25};
  s.lights[63].intensity = 3;
  const Frame f = frameOf(s);
  const GpuFrameBlock block = packFrameBlock(f);
  const double w = 143.0 / 1215.0;
  EXPECT_EQ(block.otherLights[63].color.x, float(3 * w));
  EXPECT_EQ(block.otherLights[63].color.y, float(1.5 * w));
  EXPECT_EQ(block.otherLights[63].color.z, float(0.75 * w));
  EXPECT_EQ(block.otherLights[0].color.x, 1.0f);  // colour 1, the builder's intensity 1, weight 1
}

TEST(FadeSelection, LightsJsonShowsTheWeightOnlyWhenTheSceneFades) {
  const auto fading = selectionToJson(frameOf(lineOfLights(65, 8)));
  EXPECT_EQ(fading["visible"][63]["weight"].get<double>(), 143.0 / 1215.0);
  EXPECT_EQ(fading["visible"][64]["weight"].get<double>(), 0.0);
  EXPECT_EQ(fading["visible"][0].dump(), R"({"light":0,"name":"","packed":0,"weight":1.0})");
  const auto plain = selectionToJson(frameOf(lineOfLights(65, 0)));
  EXPECT_EQ(plain["visible"][63].dump(), R"({"light":63,"name":"","packed":63})");
}

}  // namespace
}  // namespace lighting
