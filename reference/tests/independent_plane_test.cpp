// The reference renderer (SPEC 6) against an independent double-precision
// evaluation of SPEC sections 1 and 3 on plane scenes, to 1e-6 relative. The
// independent model, its scenes and the comparison live in
// testing/independent_plane (shared with the backends' tests); nothing there
// calls the project's light math, camera, transform, mesh, light evaluation or
// BVH. The lights that reach the plane (SPEC 4 and 5) are chosen by hand per
// scene and written down beside each scene builder.
#include "testing/independent_plane/independent_plane_model.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace {

using namespace independent_plane;

// Case 1: see orthographicCase.
TEST(IndependentPlane, OrthographicPointSpotsAndGrazingDirectional) {
  const PlaneCase c = orthographicCase();
  const ComparisonResult r = checkScene(c.scene, c.applied);
  EXPECT_GT(r.lit, c.scene.width * c.scene.height / 3);
}

// Case 2: see perspectiveScene for the lights and why all of them apply.
TEST(IndependentPlane, PerspectivePointAndSpotLights) {
  const PlaneCase c = perspectiveCase();
  const ComparisonResult r = checkScene(c.scene, c.applied);
  EXPECT_GT(r.lit, c.scene.width * c.scene.height / 2);
  EXPECT_GT(r.compared - r.lit, 0) << "the scene should show some background";
}

// Case 3: the whole of case 2 moved by 1e5 in x and z (SPEC 10 `stability`).
TEST(IndependentPlane, PerspectiveFarFromOrigin) {
  const PlaneCase c = perspectiveFarCase();
  const ComparisonResult r = checkScene(c.scene, c.applied);
  EXPECT_GT(r.lit, c.scene.width * c.scene.height / 2);
}

// Case 4: see lightOnSurfaceCase.
TEST(IndependentPlane, LightOnTheSurface) {
  const PlaneCase c = lightOnSurfaceCase();
  const SceneSpec& s = c.scene;
  const reference::ReferenceImages images = renderReference(s, false);
  const std::vector<Vec> expected = expectedImage(s, c.applied);
  SCOPED_TRACE("scene " + s.name);
  compareWithExpected(s, images, expected);

  // Our own evaluation, checked against the hand numbers: where p == position
  // of "p_on" its term is exactly 0, and under "p_low" the clamped distance
  // gives finalColor * (0.003 / sqrt(1e-5)) * rangeAtt / 1e-5.
  const auto without = [&](const std::string& name) {
    SceneSpec fewer = s;
    fewer.lights.erase(fewer.lights.begin() + lightIndex(s, name));
    return expectedImage(fewer, {allLightNames(fewer), {}});
  };
  EXPECT_EQ(expected[16 * s.width + 16], without("p_on")[16 * s.width + 16]);
  const double rangeAtt = square(1.0 - square(1e-5 / 16.0));
  const double peak = 1e-4 * (0.003 / std::sqrt(1e-5)) * rangeAtt / 1e-5;
  const double lowTerm = expected[20 * s.width + 8].r - without("p_low")[20 * s.width + 8].r;
  EXPECT_NEAR(lowTerm, s.plane.albedo.r * peak, 1e-12 * peak);
  EXPECT_EQ(images.value.at(8, 20, 3), 1.0f) << "the pixel under p_low must be compared";
}

// Case 5: see perObjectTruncationCase for the order of the eleven lights.
TEST(IndependentPlane, PerObjectListKeepsTheEightMostImportant) {
  const PlaneCase c = perObjectTruncationCase();
  const SceneSpec& s = c.scene;
  const std::vector<std::string>& applied = c.applied.perPixel;

  // Our own check of the hand-derived order against SPEC 5.2's formula.
  const auto importance = [&](const std::string& name) {
    const LightSpec& l = s.lights[lightIndex(s, name)];
    const double d2 = glm::dot(l.position - s.plane.centre, l.position - s.plane.centre);
    const double rangeAtt = square(saturate(1.0 - square(d2 / (l.range * l.range))));
    return luminance(l.color * l.intensity) * rangeAtt / std::max(d2, 1e-5);
  };
  ASSERT_EQ(applied.size(), 8u);
  for (std::size_t k = 1; k < applied.size(); ++k) EXPECT_GT(importance(applied[k - 1]), importance(applied[k]));
  for (const char* dropped : {"p1", "p8", "p4"}) {
    EXPECT_EQ(std::count(applied.begin(), applied.end(), dropped), 0) << dropped;
    EXPECT_GT(importance(applied.back()), importance(dropped));
  }

  const ComparisonResult r = checkScene(s, c.applied);
  EXPECT_GT(r.lit, s.width * s.height / 3);
}

// Case 6: see legacyVertexLightsCase for the list order.
TEST(IndependentPlane, LegacyVertexLights) {
  const PlaneCase c = legacyVertexLightsCase();
  const ComparisonResult r = checkScene(c.scene, c.applied);
  EXPECT_GT(r.lit, c.scene.width * c.scene.height / 3);
}

// Case 7: the scene of case 5 with --ideal (SPEC 6): all 11 lights per pixel.
TEST(IndependentPlane, IdealLightsEveryLight) {
  const PlaneCase c = idealEveryLightCase();
  const ComparisonResult r = checkScene(c.scene, c.applied, /*ideal=*/true);
  EXPECT_GT(r.lit, c.scene.width * c.scene.height / 3);
}

}  // namespace
