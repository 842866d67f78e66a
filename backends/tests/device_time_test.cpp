// Backend::lastDrawDeviceMilliseconds() on every backend and driver pair:
// after draw() of a real suite scene the device's own time is there, positive,
// and within the wall time around draw() (device work is a part of what
// draw() waits for). Speed is not asserted. Mesa's software drivers (lavapipe,
// llvmpipe, softpipe) all have a clock, so there an empty time fails the test;
// on any other device an empty time is a skip that says so, never a pass.
// Validation is on (backend_combinations.h): the queries' resets, writes and
// reads must leave the layer silent, draw after draw, with a readback between.
#include "backends/backend.h"
#include "backends/tests/backend_combinations.h"
#include "baking/bake.h"
#include "lighting/frame.h"
#include "scene_input/scene_loader.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

namespace {

using backends::testing::Combination;

// 64 point lights, every one visible: the suite's heaviest forward pass
// (64x64); and a 96x64 scene, whose new size makes the backends build new
// targets between two timed draws (on llvmpipe, a GL_TIME_ELAPSED query begun
// before a new framebuffer reaches the driver reads the whole monotonic
// clock: gl_backend.cpp).
constexpr const char* kScene = LIGHTCTS_SCENES_DIR "/limits/sixty-four-lights.json";
constexpr const char* kOtherSizeScene = LIGHTCTS_SCENES_DIR "/limits/popping-64-fade.json";
// Clock granularity and the two clocks' reads: the device time is a part of
// draw(), so only rounding can put it above the wall time.
constexpr double kSlackMilliseconds = 0.5;

bool isMesaSoftwareDriver(const backends::DeviceInfo& device) {
  // lavapipe names its device after llvmpipe.
  return device.name.find("llvmpipe") != std::string::npos || device.name.find("softpipe") != std::string::npos;
}

class DeviceTime : public ::testing::TestWithParam<Combination> {};

TEST_P(DeviceTime, IsPresentPositiveAndWithinTheWallTimeOfDraw) {
  std::string whyNot;
  const auto backend = backends::testing::createOrNull(GetParam(), whyNot);
  if (!backend) GTEST_SKIP() << whyNot;
  const backends::DeviceInfo device = backend->device();
  EXPECT_FALSE(backend->lastDrawDeviceMilliseconds().has_value()) << "a device time before any draw()";

  const lighting::Frame frame = lighting::prepareFrame(baking::prepareBakedScene(scene_input::loadSceneFile(kScene)), 0);
  const lighting::Frame other =
      lighting::prepareFrame(baking::prepareBakedScene(scene_input::loadSceneFile(kOtherSizeScene)), 0);
  ASSERT_NE(frame.scene().image.width, other.scene().image.width);
  // The pipelines' compile stays out of the timed draws.
  backend->preparePipeline(frame);
  backend->preparePipeline(other);

  const std::vector<const lighting::Frame*> draws = {&frame, &frame, &other, &frame};
  for (int draw = 0; draw < int(draws.size()); ++draw) {
    const auto start = std::chrono::steady_clock::now();
    backend->draw(*draws[draw]);
    const double wall = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    const std::optional<double> deviceTime = backend->lastDrawDeviceMilliseconds();
    if (!deviceTime) {
      if (isMesaSoftwareDriver(device))
        FAIL() << device.name << " (" << GetParam().suffix << ") has a clock, yet draw " << draw
               << " reported no device time";
      GTEST_SKIP() << device.name << " (" << GetParam().suffix
                   << ") offers no device timer (no timestamp bits on its queue, or a 0-bit GL_TIME_ELAPSED "
                      "counter): nothing to check";
    }
    std::printf("%s on %s, draw %d (%s): device %.3f ms, wall %.3f ms\n", GetParam().suffix.c_str(),
                device.name.c_str(), draw, draws[draw]->scene().name.c_str(), *deviceTime, wall);
    EXPECT_GT(*deviceTime, 0.0) << "draw " << draw;
    EXPECT_LE(*deviceTime, wall + kSlackMilliseconds) << "draw " << draw << ": device time above draw()'s wall time";
    // A readback between draws: the next draw's queries start afresh all the same.
    if (draw == 1) backend->readback();
  }
}

INSTANTIATE_TEST_SUITE_P(EveryCombination, DeviceTime, ::testing::ValuesIn(backends::testing::allCombinations()),
                         backends::testing::combinationTestName);

}  // namespace
