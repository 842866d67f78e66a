// Every GL combination against Vulkan on every suite scene: each image is
// allowed the reference's tolerance, so two correct images may differ by the
// sum of their tolerances (twice the reference's, per channel) wherever the
// mask compares. One test per combination (its own process, its own Mesa
// driver); a skip when either backend is not here.
#include "backends/backend.h"
#include "backends/tests/backend_combinations.h"
#include "backends/tests/suite_scene_renders.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace {

using backends::testing::Combination;

class GlAgreesWithVulkan : public ::testing::TestWithParam<Combination> {};

TEST_P(GlAgreesWithVulkan, OnEveryScene) {
  std::string whyNot;
  const auto vulkan = backends::testing::createOrNull({"vulkan", "vulkan", ""}, whyNot);
  if (!vulkan) GTEST_SKIP() << whyNot;
  const auto gl = backends::testing::createOrNull(GetParam(), whyNot);
  if (!gl) GTEST_SKIP() << whyNot;

  // A driver's known mismatches with SPEC (softpipe's filtered shadow
  // compares) are its own; the comparison with the reference reports them.
  const std::set<std::string> expectedFailures =
      backends::testing::expectedFailingTests(LIGHTCTS_EXPECTED_FAILURES_DIR);
  const std::string suffix = GetParam().suffix;
  const int scenes = backends::testing::forEachSuiteScene(
      LIGHTCTS_SCENES_DIR, *vulkan, *gl, [&](const backends::testing::SceneRenders& r) {
        if (expectedFailures.contains(backends::testing::sceneTestName(r.file, suffix))) return;
        const imaging::Image& a = r.first;
        const imaging::Image& b = r.second;
        ASSERT_EQ(a.width, b.width);
        ASSERT_EQ(a.height, b.height);
        long long differing = 0;
        double largestRatio = 0;
        for (int y = 0; y < a.height; ++y)
          for (int x = 0; x < a.width; ++x) {
            if (r.reference.value.at(x, y, 3) == 0.0f) continue;  // don't care (SPEC 6 mask)
            for (int c = 0; c < 3; ++c) {
              const double difference = std::abs(double(a.at(x, y, c)) - double(b.at(x, y, c)));
              const double allowed = 2.0 * r.reference.tolerance.at(x, y, c);
              if (!(difference <= allowed)) ++differing;
              if (allowed > 0) largestRatio = std::max(largestRatio, difference / allowed);
            }
          }
        EXPECT_EQ(differing, 0) << r.file << ": largest difference / allowed " << largestRatio;
      });
  EXPECT_GE(scenes, 16);
}

INSTANTIATE_TEST_SUITE_P(
    EveryGlCombination, GlAgreesWithVulkan, ::testing::ValuesIn([] {
      auto all = backends::testing::allCombinations();
      all.erase(std::remove_if(all.begin(), all.end(), [](const Combination& c) { return c.backend == "vulkan"; }),
                all.end());
      return all;
    }()),
    backends::testing::combinationTestName);

}  // namespace
