// The bench's set follows the driver's measured speed (suite/bench/driver_speed.h):
// the rule itself, on probe times written out by hand.
#include "suite/bench/driver_speed.h"

#include <gtest/gtest.h>

namespace bench {
namespace {

TEST(DriverSpeed, AProbeFrameScalesBySixteenToTheFullSize) {
  // 1280x720 is 16 times the probe's 320x180 pixels.
  EXPECT_DOUBLE_EQ(fullSizeEstimateMs(10), 160);
  EXPECT_DOUBLE_EQ(fullSizeEstimateMs(62.5), 1000);
}

TEST(DriverSpeed, TheScaledDownSetOnlyPastASecondAtFullSize) {
  EXPECT_FALSE(runsScaledDownSet(25));     // a Mesa llvmpipe-like 25 ms probe: 400 ms a full frame
  EXPECT_FALSE(runsScaledDownSet(62.5));   // exactly the limit: still the full set
  EXPECT_TRUE(runsScaledDownSet(62.6));    // past it
  EXPECT_TRUE(runsScaledDownSet(2350));    // a softpipe-like probe
}

}  // namespace
}  // namespace bench
