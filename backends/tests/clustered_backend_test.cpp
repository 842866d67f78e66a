// The clustered mode's exactness: the mode (lighting/light_clusters.h)
// drops no light that reaches a pixel, so on every combination each suite
// scene it can draw (srp, forward, without per-object lists) must pass the
// same comparison as the model's all-lights loop: every frame, against the
// same reference and the same tolerance (conformance::checkScene with
// CheckOptions::clustered). The lists come from small tiles (8 pixels, more
// where the lists would not fit a texture buffer: gridFor) and many slices
// (24), so most scenes span several clusters. The all-lights frames
// themselves are each scene's own test on every combination.
//
// Skipped scenes, with the reason: the legacy profile (its own 16-light budget
// with vertex lights; the mode is srp's), the deferred path (every deferred
// scene is a variant of a forward one, unit.scenes.deferred-variants-match-originals),
// per-object lists (the mode replaces the all-lights loop, not the lists).
#include "backends/backend.h"
#include "backends/tests/backend_combinations.h"
#include "backends/tests/suite_scene_checks.h"
#include "baking/bake.h"
#include "conformance/reference_cache.h"
#include "conformance/scene_check.h"
#include "lighting/gpu_packing.h"
#include "lighting/light_clusters.h"
#include "scene_input/scene_loader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <vector>

namespace {

using backends::testing::Combination;

constexpr lighting::ClusterGridSpec kGrid{.tileSize = 8, .depthSlices = 24};

// kGrid, with the tile doubled until frame 0's lists fit in half of the
// 65536 texels OpenGL promises a texture buffer (softpipe has no more; half,
// so an animated scene's later frames fit too).
lighting::ClusterGridSpec gridFor(const lighting::Frame& frame) {
  lighting::ClusterGridSpec grid = kGrid;
  while (lighting::packClusterTexels(lighting::binLights(frame, grid)).size() > 32768) grid.tileSize *= 2;
  return grid;
}

class ClusteredMode : public ::testing::TestWithParam<Combination> {};

TEST_P(ClusteredMode, PassesWhereAllLightsPassesOnEveryEligibleScene) {
  std::string whyNot;
  const auto backend = backends::testing::createOrNull(GetParam(), whyNot);
  if (!backend) GTEST_SKIP() << whyNot;
  const runner::ExpectedFailures expectedFailures =
      backends::testing::suiteExpectedFailures(LIGHTCTS_EXPECTED_FAILURES_DIR);

  int checked = 0, frames = 0, legacy = 0, deferred = 0, lists = 0;
  double worstTightness = 0;
  std::string worstScene;
  for (const conformance::SceneFile& sceneFile : conformance::findSceneFiles(LIGHTCTS_SCENES_DIR)) {
    const std::filesystem::path& file = sceneFile.path;
    lighting::Scene scene = scene_input::loadSceneFile(file.string());
    if (scene.pipeline.profile == lighting::Profile::Legacy) {
      ++legacy;
      continue;
    }
    if (scene.pipeline.path == lighting::RenderPath::Deferred) {
      ++deferred;
      continue;
    }
    conformance::SceneReferences references = backends::testing::cachedSceneReferences(file, std::move(scene));
    if (!references.frame(0).objectLists.empty()) {
      ++lists;
      continue;
    }
    conformance::CheckOptions options;
    options.clustered = gridFor(references.frame(0));
    const conformance::SceneCheck check = conformance::checkScene(references, *backend, options);
    ++checked;
    frames += int(check.frames.size());
    const std::string test = sceneFile.caseName() + "." + GetParam().suffix;
    // A driver's known mismatch (softpipe's filtered shadow compares) is its
    // all-lights frame's too: not the mode's to pass, nor its tightness.
    if (expectedFailures.find(test)) continue;
    EXPECT_EQ(check.verdict, comparison::Verdict::Pass)
        << test << " in the clustered mode: " << check.evidence().comparison.failingPixels
        << " failing pixels, tightness " << check.evidence().comparison.maxErrorOverTolerance;
    // An expect_fail scene's tightness is past 1 on purpose: not counted.
    for (const conformance::FrameCheck& f : check.frames)
      if (!f.comparison.expectFail && std::isfinite(f.comparison.maxErrorOverTolerance) &&
          f.comparison.maxErrorOverTolerance > worstTightness) {
        worstTightness = f.comparison.maxErrorOverTolerance;
        worstScene = test;
      }
  }
  std::cout << GetParam().suffix << ": " << checked << " scenes (" << frames << " frames) in the clustered mode ("
            << kGrid.tileSize << "-pixel tiles, " << kGrid.depthSlices << " slices); skipped " << legacy
            << " legacy, " << deferred << " deferred, " << lists
            << " with per-object lists; largest tightness (expect_fail scenes and known driver failures apart) "
            << worstTightness
            << (worstScene.empty() ? "" : " (" + worstScene + ")") << "\n";
  EXPECT_GE(checked, 40);  // the suite's srp forward scenes without lists: most of it
}

// The control: the backend reads the lists. The same scene with every
// cluster's list emptied (only the directional lights remain) must fail.
TEST_P(ClusteredMode, EmptiedListsFail) {
  std::string whyNot;
  const auto backend = backends::testing::createOrNull(GetParam(), whyNot);
  if (!backend) GTEST_SKIP() << whyNot;
  const std::filesystem::path file = std::filesystem::path(LIGHTCTS_SCENES_DIR) / "attenuation/point-d-0p8-range.json";
  lighting::Scene scene = scene_input::loadSceneFile(file.string());
  conformance::SceneReferences references(baking::prepareBakedScene(std::move(scene)));
  lighting::Frame frame = references.frame(0);
  lighting::useLightClusters(frame, kGrid);
  auto emptied = std::make_shared<lighting::LightClusters>(*frame.clusters);
  std::fill(emptied->count.begin(), emptied->count.end(), 0u);
  frame.clusters = emptied;
  const imaging::Image image = backend->render(frame);
  const comparison::Comparison c =
      comparison::compareImages(image, references.reference(0), references.prepared()->scene.expect);
  EXPECT_FALSE(c.comparisonPassed) << "a frame drawn over empty clusters passed: the lists are not read";
}

INSTANTIATE_TEST_SUITE_P(EveryCombination, ClusteredMode,
                         ::testing::ValuesIn(backends::testing::allCombinations()),
                         backends::testing::combinationTestName);

}  // namespace
