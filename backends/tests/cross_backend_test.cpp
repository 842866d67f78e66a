// Every GL combination against Vulkan on every suite scene: each image is
// allowed the reference's tolerance, so two correct images may differ by the
// sum of their tolerances (twice the reference's, per channel) wherever the
// mask compares. One test per combination (its own process, its own Mesa
// driver); a skip when either backend is not here.
#include "backends/backend.h"
#include "backends/tests/backend_combinations.h"
#include "lighting/frame.h"
#include "lighting/scene_loader.h"
#include "reference/reference_renderer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace {

using backends::testing::Combination;

class GlAgreesWithVulkan : public ::testing::TestWithParam<Combination> {};

TEST_P(GlAgreesWithVulkan, OnEveryScene) {
  std::string whyNot;
  const auto vulkan = backends::testing::createOrNull({"vulkan", "vulkan", ""}, whyNot);
  if (!vulkan) GTEST_SKIP() << whyNot;
  const auto gl = backends::testing::createOrNull(GetParam(), whyNot);
  if (!gl) GTEST_SKIP() << whyNot;

  int scenes = 0;
  for (const auto& group : std::filesystem::directory_iterator(LIGHTCTS_SCENES_DIR))
    for (const auto& file : std::filesystem::directory_iterator(group.path())) {
      const auto prepared = lighting::prepareScene(lighting::loadSceneFile(file.path().string()));
      const lighting::Frame frame = lighting::prepareFrame(prepared, 0);
      const imaging::Image a = vulkan->render(frame);
      const imaging::Image b = gl->render(frame);
      const reference::ReferenceImages ref = reference::ReferenceRenderer(prepared).render(frame);
      ASSERT_EQ(a.width, b.width);
      ASSERT_EQ(a.height, b.height);
      long long differing = 0;
      double largestRatio = 0;
      for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
          if (ref.value.at(x, y, 3) == 0.0f) continue;  // don't care (SPEC 6 mask)
          for (int c = 0; c < 3; ++c) {
            const double difference = std::abs(double(a.at(x, y, c)) - double(b.at(x, y, c)));
            const double allowed = 2.0 * ref.tolerance.at(x, y, c);
            if (!(difference <= allowed)) ++differing;
            if (allowed > 0) largestRatio = std::max(largestRatio, difference / allowed);
          }
        }
      EXPECT_EQ(differing, 0) << file.path() << ": largest difference / allowed " << largestRatio;
      ++scenes;
    }
  EXPECT_GE(scenes, 16);
}

INSTANTIATE_TEST_SUITE_P(
    EveryGlCombination, GlAgreesWithVulkan, ::testing::ValuesIn([] {
      auto all = backends::testing::allCombinations();
      all.erase(std::remove_if(all.begin(), all.end(), [](const Combination& c) { return c.backend == "vulkan"; }),
                all.end());
      return all;
    }()),
    [](const auto& info) { return info.param.suffix; });

}  // namespace
