// How the reference reads baked maps: the UV of a world point through the
// inverse object transform, the four texels of a bilinear sample, and the
// texture-filtering bound of SPEC 7, each against hand-derived values.
#include "reference/lightmap_sampling.h"

#include "reference/tolerance_model.h"

#include <gtest/gtest.h>

namespace reference {
namespace {

using namespace lighting;

TEST(LightmapSampling, UvOfAWorldPointUndoesRotationScaleAndTranslation) {
  // Plane 4 x 8; local (1, 0, -2) has u = 1/4 + 1/2 = 0.75, v = -2/8 + 1/2 = 0.25.
  MeshSpec plane;
  plane.planeSizeX = 4;
  plane.planeSizeZ = 8;
  Transform t;
  t.rotateDeg = {0, 90, 30};
  t.scale = 2;
  t.translate = {1, -3, 5};
  const ObjectTransform transform = objectTransform(t);
  const Vec2 uv = lightmapUvOfWorldPoint(plane, transform, transform.applyToPoint({1, 0, -2}));
  EXPECT_NEAR(uv.x, 0.75, 1e-14);
  EXPECT_NEAR(uv.y, 0.25, 1e-14);
}

TEST(LightmapSampling, FootprintOfAnInteriorSample) {
  // N = 4, u = 0.5: x = 0.5 * 4 - 0.5 = 1.5, so texels 1 and 2 with fx = 0.5;
  // v = 0.3: y = 0.7, texels 0 and 1 with fy = 0.7.
  const TexelFootprint f = texelFootprint(4, {0.5, 0.3});
  EXPECT_EQ(f.i0, 1);
  EXPECT_EQ(f.i1, 2);
  EXPECT_EQ(f.j0, 0);
  EXPECT_EQ(f.j1, 1);
  EXPECT_DOUBLE_EQ(f.fx, 0.5);
  EXPECT_NEAR(f.fy, 0.7, 1e-15);
}

TEST(LightmapSampling, FootprintClampsToTheEdge) {
  // u = 0.01: x = -0.46, floor -1: both texels clamp to 0; v = 0.99:
  // y = 3.46, texel 3 and 4 -> 3.
  const TexelFootprint f = texelFootprint(4, {0.01, 0.99});
  EXPECT_EQ(f.i0, 0);
  EXPECT_EQ(f.i1, 0);
  EXPECT_EQ(f.j0, 3);
  EXPECT_EQ(f.j1, 3);
}

TEST(LightmapSampling, FootprintBlendAgreesWithSampleBilinear) {
  // Two implementations of one rule (lighting/baked_lighting.cpp and the
  // footprint the real-time comparison uses) must pick the same texels.
  TexelMap map{5, std::vector<float>(5 * 5 * 4)};
  for (int k = 0; k < 5 * 5 * 4; ++k) map.texels[k] = float((k * 37) % 11) / 8.0f;
  for (const Vec2 uv : {Vec2(0.03, 0.97), Vec2(0.5, 0.5), Vec2(0.61, 0.12), Vec2(1.0, 0.0), Vec2(0.3, 0.7)}) {
    const TexelFootprint f = texelFootprint(5, uv);
    const Vec4 expected = sampleBilinear(map, uv).value;
    const Vec4 blend = (map.texel(f.i0, f.j0) * (1 - f.fx) + map.texel(f.i1, f.j0) * f.fx) * (1 - f.fy) +
                       (map.texel(f.i0, f.j1) * (1 - f.fx) + map.texel(f.i1, f.j1) * f.fx) * f.fy;
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(blend[c], expected[c], 1e-15) << uv.x << " " << uv.y;
  }
}

TEST(LightmapSampling, FilteringBoundByHand) {
  // Spread 0.5, magnitude 1, N = 8:
  //   weights: 2 x 2^-4 x 0.5 = 0.0625
  //   UV:      2 x 8 x 0.5 x 16 u = 128 u
  //   blend:   6 u x 1
  const double u = tolerance::kStepRoundoff;  // one GPU operation's rounding
  EXPECT_DOUBLE_EQ(filteringErrorBound(0.5, 1.0, 8), 0.0625 + 128 * u + 6 * u);
  // A flat neighbourhood leaves only the blend's rounding.
  EXPECT_DOUBLE_EQ(filteringErrorBound(0.0, 2.0, 8), 12 * u);
}

TEST(LightmapSampling, FilteringBoundOfASampleUsesEachChannelsSpread) {
  // Texels 0 and 1 along u (N = 2, v in the middle row pair): channel 0 goes
  // from 0 to 1, channel 1 is flat at 0.5.
  TexelMap map{2, std::vector<float>(2 * 2 * 4, 0.5f)};
  map.texels[0] = 0.0f;   // (0, 0)
  map.texels[4] = 1.0f;   // (1, 0)
  map.texels[8] = 0.0f;   // (0, 1)
  map.texels[12] = 1.0f;  // (1, 1)
  const BilinearSample s = sampleBilinear(map, {0.5, 0.5});
  EXPECT_DOUBLE_EQ(s.value[0], 0.5);
  const Vec4 bound = filteringErrorBound(s, 2);
  const double u = tolerance::kStepRoundoff;  // one GPU operation's rounding
  // Channel 0: spread 1, magnitude <= 0.5 + 1: 0.125 + 2*2*16 u + 6 u * 1.5.
  EXPECT_DOUBLE_EQ(bound[0], 0.125 + 64 * u + 9 * u);
  // Channel 1: spread 0, magnitude 0.5.
  EXPECT_DOUBLE_EQ(bound[1], 3 * u);
}

}  // namespace
}  // namespace reference
