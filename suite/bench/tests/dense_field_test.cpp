// The dense field (bench_scenes.h, kDenseFieldRangeScale): every
// object's list (SPEC 5.2, before the cut to 8) holds 20 or more lights, the
// fewest 23: a corner tile, whose bounding sphere (radius 0.918) meets the
// range spheres (4.675) of the 23 grid lights within 5.59 of its centre
// (docs/bench-format.md derives it by hand).
#include "lighting/frame.h"
#include "suite/bench/bench_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace {

using namespace lighting;

TEST(DenseField, EveryObjectIsTouchedByTwentyThreeLightsOrMore) {
  bench::FieldSpec field;
  field.mode = bench::FrameMode::PerObject;
  field.rangeScale = bench::kDenseFieldRangeScale;
  const Frame frame = prepareFrame(prepareScene(bench::fieldScene(field, "dense")), 0);
  ASSERT_FALSE(frame.objectLists.empty());
  int fewest = 1 << 30;
  for (const ObjectLightList& list : frame.objectLists) fewest = std::min(fewest, list.count);
  EXPECT_EQ(fewest, 23);
  EXPECT_GE(fewest, bench::kDenseFieldLeastObjectLights);
}

// The 64-light field itself is not dense: some object's list fits the 8 a
// list keeps, so per-object lists are exact there (its error equals all-lights').
TEST(DenseField, TheSixtyFourLightFieldIsNot) {
  bench::FieldSpec field;
  field.mode = bench::FrameMode::PerObject;
  const Frame frame = prepareFrame(prepareScene(bench::fieldScene(field, "sparse")), 0);
  int most = 0;
  for (const ObjectLightList& list : frame.objectLists) most = std::max(most, list.count);
  EXPECT_LE(most, 8);
}

}  // namespace
