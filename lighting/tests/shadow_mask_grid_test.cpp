// The grid version of the shadow-mask assignment (SPEC 5.3) gives exactly the
// brute-force greedy's answer: the same entries, channels and demotions.
#include "lighting/shadow_mask_channels.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>

namespace lighting {
namespace {

class Random {
 public:
  explicit Random(std::uint64_t seed) : state_(seed) {}
  double uniform(double low, double high) {
    state_ = state_ * 6364136223846793005ull + 1442695040888963407ull;
    return low + (high - low) * double(state_ >> 11) * 0x1.0p-53;
  }
  int below(int n) { return int(uniform(0, n)); }

 private:
  std::uint64_t state_;
};

void expectSameAssignment(const Scene& scene) {
  const ShadowMaskAssignment grid = assignShadowMaskChannels(scene);
  const ShadowMaskAssignment brute = assignShadowMaskChannelsBruteForce(scene);
  ASSERT_EQ(grid.entries.size(), brute.entries.size());
  for (std::size_t i = 0; i < grid.entries.size(); ++i) {
    EXPECT_EQ(grid.entries[i].light, brute.entries[i].light) << "entry " << i;
    EXPECT_EQ(grid.entries[i].channel, brute.entries[i].channel) << "entry " << i;
    EXPECT_EQ(grid.entries[i].demoted, brute.entries[i].demoted) << "entry " << i;
  }
  EXPECT_EQ(grid.channelOfLight, brute.channelOfLight);
  EXPECT_EQ(grid.demotedLight, brute.demotedLight);
}

Light mixedLight(Vec3 position, double range, LightType type = LightType::Point) {
  Light l;
  l.type = type;
  l.position = position;
  l.range = range;
  l.mode = LightMode::Mixed;
  l.shadows = true;
  l.shadowStrength = 1;
  return l;
}

TEST(ShadowMaskGrid, MatchesBruteForceOnRandomScenes) {
  for (int seed = 1; seed <= 40; ++seed) {
    Random random{std::uint64_t(seed)};
    Scene scene;
    const int count = 50 + random.below(400);
    const double half = 2 + random.uniform(0, 30);
    for (int i = 0; i < count; ++i) {
      const int kind = random.below(20);
      Light l = mixedLight({random.uniform(-half, half), random.uniform(-half, half), random.uniform(-half, half)},
                           random.uniform(0.2, 3), i % 3 == 0 ? LightType::Spot : LightType::Point);
      if (kind == 0) l.range = random.uniform(10, 80);      // too large for the grid
      if (kind == 1) l.range = 0;                          // a point
      if (kind == 2) l.type = LightType::Directional;      // overlaps everything
      if (kind == 3) l.mode = LightMode::Realtime;         // not a candidate
      if (kind == 4) l.shadowStrength = 0;                 // not a candidate
      if (kind == 5 && i > 0) l.position = scene.lights[std::size_t(random.below(i))].position;  // coincident
      l.intensity = 1 + random.below(3);                   // ties in luminance * range^2
      l.name = "l" + std::to_string(i);
      scene.lights.push_back(l);
    }
    SCOPED_TRACE("seed " + std::to_string(seed));
    expectSameAssignment(scene);
  }
}

// Spheres that touch exactly (|p1 - p2| == r1 + r2 in binary) do not overlap;
// a hair closer they do. The grid must find the close pairs on cell borders.
TEST(ShadowMaskGrid, TouchingAndNearlyTouchingSpheres) {
  Scene scene;
  for (int i = 0; i < 40; ++i) {
    scene.lights.push_back(mixedLight({2.0 * i, 0, 0}, 1.0));
    scene.lights.push_back(mixedLight({2.0 * i - 1e-12, 4, 0}, 1.0));
    scene.lights.push_back(mixedLight({1e6 + 2.0 * i, 0, 0}, 1.0));  // far from the origin
    scene.lights.push_back(mixedLight({-1e6 - 1.999999 * i, 0, 0}, 1.0));
  }
  expectSameAssignment(scene);
}

// Ranges from 0.05 to 3 in a field a few ranges wide: small lights near the
// border of a large one's reach, many demotions.
TEST(ShadowMaskGrid, VariedRangesInAFieldMatchBruteForce) {
  for (int seed = 1; seed <= 20; ++seed) {
    Random random{std::uint64_t(1000 + seed)};
    Scene scene;
    const double side = 5 + 5 * seed;
    for (int i = 0; i < 600; ++i)
      scene.lights.push_back(mixedLight({random.uniform(0, side), random.uniform(0, 3), random.uniform(0, side)},
                                        random.uniform(0, 1) < 0.7 ? random.uniform(0.05, 0.5) : random.uniform(1, 3)));
    SCOPED_TRACE("seed " + std::to_string(seed));
    expectSameAssignment(scene);
  }
}

TEST(ShadowMaskGrid, DenseClusterDemotesLikeBruteForce) {
  Scene scene;
  Random random(7);
  for (int i = 0; i < 300; ++i) scene.lights.push_back(mixedLight({random.uniform(0, 1), 0, random.uniform(0, 1)}, 0.5));
  expectSameAssignment(scene);
}

}  // namespace
}  // namespace lighting
