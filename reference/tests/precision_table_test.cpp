// ulpAt against Vulkan's definition of ulp(x) for float32, by hand: the gap
// between the two floats around x is 2^(e - 23) for |x| in [2^e, 2^(e+1)),
// 2^-149 below the smallest normal, and infinity or NaN carries through.
#include "reference/precision_table.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace reference {
namespace {

TEST(UlpAt, IsTheGapBetweenFloatsAcrossEachBinade) {
  EXPECT_EQ(ulpAt(1.0), 0x1p-23);
  EXPECT_EQ(ulpAt(1.5), 0x1p-23);
  EXPECT_EQ(ulpAt(std::nextafter(2.0, 0.0)), 0x1p-23);  // the top of [1, 2)
  EXPECT_EQ(ulpAt(2.0), 0x1p-22);
  EXPECT_EQ(ulpAt(0.75), 0x1p-24);
  EXPECT_EQ(ulpAt(1000.0), 0x1p-14);                   // 1000 in [512, 1024)
  EXPECT_EQ(ulpAt(3.0e38), 0x1p104);                   // the top binade, [2^127, 2^128)
}

TEST(UlpAt, IsTheDenormalStepBelowTheNormals) {
  EXPECT_EQ(ulpAt(0x1p-126), 0x1p-149);  // the smallest normal: 2^(-126 - 23)
  EXPECT_EQ(ulpAt(0x1p-127), 0x1p-149);
  EXPECT_EQ(ulpAt(0.0), 0x1p-149);
}

TEST(UlpAt, IsTheMagnitudeItselfPastTheFloatsAndForNaN) {
  EXPECT_EQ(ulpAt(std::numeric_limits<double>::infinity()), std::numeric_limits<double>::infinity());
  EXPECT_EQ(ulpAt(0x1p128), 0x1p128);
  EXPECT_TRUE(std::isnan(ulpAt(std::numeric_limits<double>::quiet_NaN())));
}

}  // namespace
}  // namespace reference
