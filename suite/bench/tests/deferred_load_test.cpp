// bench::DeferredCoverage (the deferred modes' lights_per_pixel): a pixel
// counts a light volume when its ray leaves the volume at or behind the
// surface it hits. One point light of range 2 at (0, 1, 0), seen from straight
// above: its icosphere encloses the range sphere, and with the 80-face
// icosphere (inscribed radius 0.934 of its circumradius) and a small safety
// margin its vertices lie about 2.2 from the light; the cases below hold for
// any circumradius between 2 and 2.5. So the vertical ray through x = z = 0
// leaves it between y = -1 and y = -1.5, and a ray 3 units to the side misses it.
#include "suite/bench/deferred_load.h"

#include "lighting/frame.h"

#include <gtest/gtest.h>

namespace {

using namespace lighting;

Frame topDownFrame(bool withDirectional) {
  Scene s;
  s.name = "deferred-load";
  s.image = {64, 64};
  s.camera = Camera{{0, 10, 0}, {0, 0, 0}, {0, 0, -1}, Projection::Orthographic, 60, 10, 0.1, 100};
  s.pipeline.path = RenderPath::Deferred;
  Object floor;
  floor.mesh.type = MeshType::Plane;
  s.objects.push_back(floor);
  Light point;
  point.type = LightType::Point;
  point.position = {0, 1, 0};
  point.range = 2;
  s.lights.push_back(point);
  if (withDirectional) {
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = {0, -1, 0};
    s.lights.push_back(sun);
  }
  return prepareFrame(prepareScene(s), 0);
}

// Straight down from height 10 at (x, z): the hit at height y is 10 - y away.
Ray down(double x, double z) { return Ray{{x, 10, z}, {0, -1, 0}}; }

TEST(DeferredCoverage, SurfaceInsideTheVolumeIsShaded) {
  const bench::DeferredCoverage coverage(topDownFrame(false));
  EXPECT_EQ(coverage.volumesShading(down(0, 0), 10.0), 1);   // the floor under the light
  EXPECT_EQ(coverage.volumesShading(down(0, 0), 11.0), 1);   // y = -1: on the range sphere
  EXPECT_EQ(coverage.volumesShading(down(1, -1), 10.0), 1);  // 1.7 from the light
}

TEST(DeferredCoverage, SurfaceInFrontOfTheVolumeIsShadedBehindItIsNot) {
  const bench::DeferredCoverage coverage(topDownFrame(false));
  // y = 5 lies above the volume (at most 1 + 2.5): the back faces are behind it.
  EXPECT_EQ(coverage.volumesShading(down(0, 0), 5.0), 1);
  // y = -2 lies below it (at least 1 - 2.5 = -1.5): the volume is in front.
  EXPECT_EQ(coverage.volumesShading(down(0, 0), 12.0), 0);
}

TEST(DeferredCoverage, RayBesideTheVolumeMissesIt) {
  const bench::DeferredCoverage coverage(topDownFrame(false));
  EXPECT_EQ(coverage.volumesShading(down(3, 0), 10.0), 0);
  EXPECT_EQ(coverage.volumesShading(down(0, -3), 10.0), 0);
}

TEST(DeferredCoverage, DirectionalLightsShadeEveryPixel) {
  const bench::DeferredCoverage coverage(topDownFrame(true));
  EXPECT_EQ(coverage.volumesShading(down(0, 0), 10.0), 2);
  EXPECT_EQ(coverage.volumesShading(down(3, 0), 10.0), 1);
  EXPECT_EQ(coverage.volumesShading(down(0, 0), 12.0), 1);
}

}  // namespace
