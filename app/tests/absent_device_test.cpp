// `lightcts compare` asked for a device that is not here: a skip (exit 3,
// NotSupported), never a pass (0). It loads the real Vulkan loader and the
// OSMesa library to look for the device, so it is a driver test.
#include "app/commands.h"
#include "app/exit_status.h"

#include <gtest/gtest.h>

#include <sstream>
#include <string>

namespace app {
namespace {

const std::string kScene = std::string(LIGHTCTS_SOURCE_DIR) + "/suite/scenes/attenuation/point-d-zero.json";

TEST(AbsentDevice, VulkanDeviceThatIsNotHereIsNotSupported) {
  std::ostringstream out, err;
  EXPECT_EQ(runCompareCommand({kScene, 0}, {.backend = "vulkan", .device = "no-such-device"}, "", true, out, err),
            kExitNotSupported)
      << err.str();
}

TEST(AbsentDevice, OsmesaHasNoDeviceIndexAndIsNotSupported) {
  std::ostringstream out, err;
  EXPECT_EQ(runCompareCommand({kScene, 0}, {.backend = "gl-osmesa", .device = "0"}, "", true, out, err),
            kExitNotSupported)
      << err.str();
}

}  // namespace
}  // namespace app
