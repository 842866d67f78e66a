// SPEC 3.8 in double against hand numbers.
#include "lighting/brdf.h"

#include <gtest/gtest.h>

#include <cmath>

namespace lighting {
namespace {

TEST(Brdf, MaterialColoursOfSpec38) {
  Object o;
  o.albedo = {0.8, 0.5, 0.2};
  EXPECT_EQ(materialBrdf(o).diffuse, o.albedo);  // Lambert: A, no lobe
  EXPECT_FALSE(materialBrdf(o).lobe);
  o.brdf = Brdf::Srp;
  o.metallic = 0.25;
  o.smoothness = 0.8;
  const MaterialBrdf b = materialBrdf(o);
  EXPECT_TRUE(b.lobe);
  // diffuse = A * 0.96 * 0.75 = 0.72 A; F0 = 0.04 + 0.25 (A - 0.04); roughness = 0.2^2.
  EXPECT_NEAR(b.diffuse.r, 0.576, 1e-15);
  EXPECT_NEAR(b.specular.r, 0.23, 1e-15);
  EXPECT_NEAR(b.specular.b, 0.08, 1e-15);
  EXPECT_NEAR(b.roughness, 0.04, 1e-15);
}

TEST(Brdf, PeakOfSmoothness0p9) {
  // N = V = L: H = N, nh2 = lh2 = 1; r2 = 1e-4, d = 1e-4 + 1e-5, k = 2.04:
  // 1e-4 / (1.21e-8 * 1 * 2.04) = 4051.20725976...
  // Even double feels the peak's conditioning: d = 1e-4 - 1 + 1.00001 keeps
  // only 1e-16 / 1.1e-4 ~ 1e-12 relative, so 1e-11 relative is allowed.
  const Vec3 up(0, 1, 0);
  const double expected = 1e-4 / (1.21e-8 * 2.04);
  EXPECT_NEAR(specularStrength(up, up, up, 0.01), expected, 1e-11 * expected);
  EXPECT_NEAR(expected, 4051.2072597634, 1e-9);
}

TEST(Brdf, SmoothnessOneHasNoLobeAndLOppositeVIsFinite) {
  const Vec3 up(0, 1, 0);
  EXPECT_EQ(specularStrength(up, up, up, 0.0), 0.0);
  // L = -V: SafeNormalize gives H = 0, nh2 = lh2 = 0, lh2 floored at 0.1:
  // r2 / (1.00001^2 * 0.1 * (4 r + 2)).
  const double r = 0.25;
  const double s = specularStrength(up, up, -up, r);
  EXPECT_TRUE(std::isfinite(s));
  EXPECT_NEAR(s, r * r / (1.00001 * 1.00001 * 0.1 * (4 * r + 2)), 1e-15);
  EXPECT_EQ(safeNormalize(Vec3(0.0)), Vec3(0.0));
}

}  // namespace
}  // namespace lighting
