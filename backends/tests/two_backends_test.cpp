// Two backends of one combination alive in one process (what a benchmark or
// a worker that switches shader variants does): each must draw in its own
// context, whatever the other made current or released: a GL backend that
// draws into a context another has destroyed fails it.
// The images are checked against each other, bit for bit: the same scene on
// the same driver must give the same pixels.
#include "backends/backend.h"
#include "backends/tests/backend_combinations.h"
#include "baking/bake.h"
#include "lighting/frame.h"
#include "scene_input/scene_loader.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>

namespace {

using backends::testing::Combination;

constexpr const char* kSixtyFourLightsScene = LIGHTCTS_SCENES_DIR "/limits/sixty-four-lights.json";

class TwoBackends : public ::testing::TestWithParam<Combination> {};

TEST_P(TwoBackends, EachDrawsInItsOwnContextWhileTheOtherLivesAndDies) {
  std::string whyNot;
  auto first = backends::testing::createOrNull(GetParam(), whyNot);
  if (!first) GTEST_SKIP() << whyNot;
  const lighting::Frame frame = lighting::prepareFrame(baking::prepareBakedScene(scene_input::loadSceneFile(kSixtyFourLightsScene)), 0);
  const imaging::Image before = first->render(frame);

  auto second = backends::testing::createOrNull(GetParam(), whyNot);
  ASSERT_TRUE(second) << whyNot;
  const imaging::Image fromSecond = second->render(frame);
  const imaging::Image afterSecondDrew = first->render(frame);
  second.reset();  // releases its context: the first must still draw
  const imaging::Image afterSecondDied = first->render(frame);

  EXPECT_EQ(fromSecond.pixels, before.pixels);
  EXPECT_EQ(afterSecondDrew.pixels, before.pixels);
  EXPECT_EQ(afterSecondDied.pixels, before.pixels);
}

INSTANTIATE_TEST_SUITE_P(EveryCombination, TwoBackends, ::testing::ValuesIn(backends::testing::allCombinations()),
                         backends::testing::combinationTestName);

}  // namespace
