// The Forward+ binning (lighting/light_clusters.h) against brute force on
// random scenes: points sampled in the view frustum (a random pixel position,
// a random view depth between near and far), each placed in its cluster by
// the test's own arithmetic (tile = pixel / tile size; slice from the depth
// by the definition in the header, written again here), must find in that
// cluster's list every kept point or spot light whose range sphere holds the
// point. That is the binning's promise: no light that can reach a pixel is
// missing from its cluster. The test also bounds how loose the binning is.
#include "lighting/light_clusters.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>
#include <stdexcept>

namespace lighting {
namespace {

struct RandomScene {
  Scene scene;
  ClusterGridSpec spec;
};

RandomScene randomScene(std::mt19937& rng, bool perspective) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  RandomScene r;
  Scene& s = r.scene;
  s.image = {96 + int(unit(rng) * 200), 64 + int(unit(rng) * 120)};
  s.camera.projection = perspective ? Projection::Perspective : Projection::Orthographic;
  s.camera.position = {unit(rng) * 4 - 2, 6 + unit(rng) * 6, unit(rng) * 4 - 2};
  s.camera.target = {unit(rng) * 2 - 1, 0, unit(rng) * 2 - 1};
  s.camera.up = {0, 0, -1};
  s.camera.fovYDeg = 30 + unit(rng) * 60;
  s.camera.orthoHeight = 6 + unit(rng) * 10;
  s.camera.nearPlane = 0.05 + unit(rng) * 0.5;
  s.camera.farPlane = 20 + unit(rng) * 30;
  Object floor;
  floor.mesh.planeSizeX = floor.mesh.planeSizeZ = 12;
  s.objects.push_back(floor);
  const int lights = 8 + int(unit(rng) * 120);
  for (int i = 0; i < lights; ++i) {
    Light l;
    l.type = unit(rng) < 0.5 ? LightType::Point : LightType::Spot;
    l.position = {unit(rng) * 16 - 8, unit(rng) * 6 - 1, unit(rng) * 16 - 8};
    l.direction = glm::normalize(Vec3(unit(rng) - 0.5, -1, unit(rng) - 0.5));
    l.range = 0.2 + unit(rng) * 5;
    s.lights.push_back(l);
  }
  if (unit(rng) < 0.5) {
    Light sun;
    sun.type = LightType::Directional;
    s.lights.push_back(sun);
  }
  r.spec.tileSize = std::vector<int>{1, 4, 8, 16, 32, 64}[std::size_t(unit(rng) * 6)];
  r.spec.depthSlices = 1 + int(unit(rng) * 24);
  return r;
}

// The slice of a view depth, from the header's definition: exponential
// (perspective) or linear (orthographic) between near and far.
int sliceByDefinition(const Camera& camera, int slices, double z) {
  const double n = camera.nearPlane, f = camera.farPlane;
  const double fraction =
      camera.projection == Projection::Perspective ? std::log(z / n) / std::log(f / n) : (z - n) / (f - n);
  return std::clamp(int(std::floor(fraction * slices)), 0, slices - 1);
}

class LightClustersTest : public ::testing::TestWithParam<bool> {};

TEST_P(LightClustersTest, EveryLightThatReachesAPointIsInItsCluster) {
  std::mt19937 rng(GetParam() ? 2101u : 2102u);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  // Over the sampled points: lights listed, lights that reach them, lights kept.
  double binnedPairs = 0, touchingPairs = 0, keptPairs = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const RandomScene r = randomScene(rng, GetParam());
    const Frame frame = prepareFrame(prepareScene(r.scene), 0);
    const LightClusters clusters = binLights(frame, r.spec);
    const ClusterGrid& grid = clusters.grid;
    ASSERT_EQ(grid.tilesX, (frame.view.width + r.spec.tileSize - 1) / r.spec.tileSize);
    ASSERT_EQ(grid.tilesY, (frame.view.height + r.spec.tileSize - 1) / r.spec.tileSize);
    ASSERT_EQ(clusters.first.size(), std::size_t(grid.tilesX * grid.tilesY * grid.slices));
    const std::vector<int>& packed = frame.selection.packed.other;
    for (int sample = 0; sample < 3000; ++sample) {
      const double px = unit(rng) * frame.view.width, py = unit(rng) * frame.view.height;
      const double z = frame.view.camera.nearPlane +
                       unit(rng) * (frame.view.camera.farPlane - frame.view.camera.nearPlane);
      const Ray ray = frame.view.rayThroughPixel(px, py);
      const Vec3 p = ray.origin + ray.direction * ((z - frame.view.viewDepth(ray.origin)) /
                                                   glm::dot(ray.direction, frame.view.forward));
      const int tx = int(px) / r.spec.tileSize, ty = int(py) / r.spec.tileSize;
      const int s = sliceByDefinition(frame.view.camera, r.spec.depthSlices, z);
      const int c = (s * grid.tilesY + ty) * grid.tilesX + tx;
      const auto begin = clusters.lights.begin() + clusters.first[std::size_t(c)];
      const auto end = begin + clusters.count[std::size_t(c)];
      binnedPairs += double(clusters.count[std::size_t(c)]);
      keptPairs += double(packed.size());
      for (std::size_t k = 0; k < packed.size(); ++k) {
        const Light& light = r.scene.lights[std::size_t(packed[k])];
        if (glm::distance(p, light.position) > light.range) continue;
        touchingPairs += 1;
        ASSERT_NE(std::find(begin, end, std::uint32_t(k)), end)
            << "trial " << trial << ": packed light " << k << " reaches the point at pixel (" << px << ", " << py
            << "), depth " << z << ", but is not in cluster (" << tx << ", " << ty << ", " << s << ")";
      }
    }
    for (std::size_t c = 0; c < clusters.count.size(); ++c) {
      ASSERT_TRUE(std::is_sorted(clusters.lights.begin() + clusters.first[c],
                                 clusters.lights.begin() + clusters.first[c] + clusters.count[c]))
          << "a cluster's lights are in packed order";
      for (std::uint32_t i = 0; i < clusters.count[c]; ++i)
        ASSERT_LT(clusters.lights[clusters.first[c] + i], packed.size());
    }
  }
  // It culls, which is the mode's point: a sampled point's cluster lists
  // at most a quarter of the kept lights (a sanity bound, not a tolerance:
  // measured 0.14 perspective, 0.09 orthographic on these scenes, whose
  // ranges of 0.2 to 5.2 cover a small part of a 16 x 16 field each). How
  // loose it is against the lights that reach the point is information:
  // 5.9x and 5.4x here, the box of a cluster 1 to 64 pixels wide and up to a
  // whole depth range deep being much larger than a point.
  ASSERT_GT(touchingPairs, 1000);
  EXPECT_LT(binnedPairs / keptPairs, 0.25);
}

INSTANTIATE_TEST_SUITE_P(Projections, LightClustersTest, ::testing::Values(true, false),
                         [](const auto& info) { return info.param ? "Perspective" : "Orthographic"; });

TEST(LightClusters, SliceOfFollowsItsDefinitionAndTheShaderConstants) {
  Scene s;
  s.camera.projection = Projection::Perspective;
  s.camera.nearPlane = 0.1;
  s.camera.farPlane = 100;
  Object floor;
  s.objects.push_back(floor);
  const Frame frame = prepareFrame(prepareScene(s), 0);
  const ClusterGrid grid = clusterGridFor(frame.view, {16, 3});
  // 0.1 * 1000^(1/3) = 1, 0.1 * 1000^(2/3) = 10: the slices are [0.1, 1), [1, 10), [10, 100].
  EXPECT_NEAR(grid.sliceStart(1), 1.0, 1e-12);
  EXPECT_NEAR(grid.sliceStart(2), 10.0, 1e-12);
  EXPECT_EQ(grid.sliceOf(0.5), 0);
  EXPECT_EQ(grid.sliceOf(5), 1);
  EXPECT_EQ(grid.sliceOf(50), 2);
  EXPECT_EQ(grid.sliceOf(1000), 2);  // clamped
  EXPECT_EQ(grid.sliceOf(0.01), 0);
  // The shader's floor(log(z) * scale + bias): scale = 3 / ln 1000, bias = -ln 0.1 * scale.
  EXPECT_NEAR(grid.sliceScale(), 3 / std::log(1000.0), 1e-12);
  EXPECT_NEAR(grid.sliceBias(), -std::log(0.1) * 3 / std::log(1000.0), 1e-12);
}

TEST(LightClusters, ALightIsOnlyInTheClustersItsSphereReaches) {
  Scene s;  // SPEC 2's default: orthographic from (0, 10, 0) down, height 10, near 0.1, far 100
  Object floor;
  s.objects.push_back(floor);
  Light inside;
  inside.type = LightType::Point;
  inside.position = {0, 0, 0};
  inside.range = 1;
  Light beside = inside;
  beside.position = {5.8, 0, 0};  // 0.8 beyond the frustum's side x = 5 with range 1: visible, kept
  s.lights = {inside, beside};
  const Frame frame = prepareFrame(prepareScene(s), 0);
  ASSERT_EQ(frame.selection.packed.other.size(), 2u);
  const LightClusters clusters = binLights(frame, {16, 4});
  // The floor at depth 10 in slice floor((10 - 0.1) / 99.9 * 4) = 0; the
  // sphere spans depths 9..11 only: slice 0 alone.
  for (int slice = 1; slice < 4; ++slice)
    for (int c = clusters.grid.clusterIndex(0, 0, slice); c < clusters.grid.clusterIndex(0, 0, slice + 1); ++c)
      EXPECT_EQ(clusters.count[std::size_t(c)], 0u) << "slice " << slice;
  // Light 1 (x from 4.8 to 6.8) reaches the last column of tiles only: x 4.8
  // is pixel (4.8 + 5) / 10 * 128 = 125.4 of 128, in tile 7 of 8.
  for (std::size_t c = 0; c < clusters.count.size(); ++c) {
    const int tx = int(c) % clusters.grid.tilesX;
    const auto begin = clusters.lights.begin() + clusters.first[c];
    const bool hasBeside = std::find(begin, begin + clusters.count[c], 1u) != begin + clusters.count[c];
    if (hasBeside) {
      EXPECT_EQ(tx, clusters.grid.tilesX - 1) << "cluster " << c;
    }
  }
}

TEST(LightClusters, RejectsAnEmptyGrid) {
  Scene s;
  Object floor;
  s.objects.push_back(floor);
  const Frame frame = prepareFrame(prepareScene(s), 0);
  EXPECT_THROW(binLights(frame, {0, 16}), std::invalid_argument);
  EXPECT_THROW(binLights(frame, {16, 0}), std::invalid_argument);
  Scene legacy = s;
  legacy.pipeline.profile = Profile::Legacy;  // the clustered mode is the srp profile's
  EXPECT_THROW(binLights(prepareFrame(prepareScene(legacy), 0), {16, 16}), std::invalid_argument);
}

// useLightClusters marks the frame and keeps the lists; it refuses what the
// mode does not draw (the legacy profile, the deferred path, per-object lists).
TEST(LightClusters, UseLightClustersMarksTheFrameOrRefusesIt) {
  Scene s;
  Object floor;
  floor.mesh.planeSizeX = floor.mesh.planeSizeZ = 4;
  s.objects.push_back(floor);
  Light point;
  point.type = LightType::Point;
  point.position = {0, 1, 0};
  point.range = 2;
  s.lights.push_back(point);
  Frame frame = prepareFrame(prepareScene(s), 0);
  ASSERT_FALSE(frame.clusters);
  useLightClusters(frame, {8, 4});
  ASSERT_TRUE(frame.clusters);
  EXPECT_TRUE(frame.features.clusteredLights);
  EXPECT_EQ(frame.clusters->grid.tileSize, 8);
  EXPECT_EQ(frame.clusters->grid.slices, 4);
  EXPECT_GT(frame.clusters->lights.size(), 0u);

  for (const auto& change : std::vector<std::function<void(Scene&)>>{
           [](Scene& x) { x.pipeline.profile = Profile::Legacy; },
           [](Scene& x) { x.pipeline.path = RenderPath::Deferred; },
           [](Scene& x) { x.pipeline.lightsPerObject = true; }}) {
    Scene refused = s;
    change(refused);
    Frame f = prepareFrame(prepareScene(refused), 0);
    EXPECT_THROW(useLightClusters(f, {8, 4}), std::invalid_argument);
    EXPECT_FALSE(f.clusters);
  }
}

}  // namespace
}  // namespace lighting
