// The Vulkan backend on the machine's real driver (lavapipe in CI): device
// choice, that validation messages fail a render, the readback's orientation,
// and that the full pipeline passes every scene as the specialised one does.
#include "backends/backend.h"
#include "backends/tests/suite_scene_checks.h"
#include "backends/vulkan/draw_timestamps.h"
#include "backends/vulkan/vulkan_device.h"
#include "baking/bake.h"
#include "lighting/frame.h"
#include "reference/reference_renderer.h"
#include "scene_input/scene_loader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

namespace {

using backends::DeviceInfo;
using backends::NotSupportedError;

std::vector<DeviceInfo> devices(std::initializer_list<const char*> names) {
  std::vector<DeviceInfo> out;
  for (const char* n : names) out.push_back({n, "driver", "1.0", "1.3", ""});
  return out;
}

TEST(VulkanDeviceChoice, DefaultIsTheFirstDevice) {
  EXPECT_EQ(backends::vulkan::chooseDevice(devices({"llvmpipe", "NVIDIA H100"}), ""), 0u);
}

TEST(VulkanDeviceChoice, ByIndexOrCaseInsensitiveNameSubstring) {
  const auto list = devices({"llvmpipe (LLVM 15)", "NVIDIA H100 80GB"});
  EXPECT_EQ(backends::vulkan::chooseDevice(list, "1"), 1u);
  EXPECT_EQ(backends::vulkan::chooseDevice(list, "h100"), 1u);
  EXPECT_EQ(backends::vulkan::chooseDevice(list, "LLVM"), 0u);
}

TEST(VulkanDeviceChoice, NothingMatchingIsNotSupportedAndListsTheDevices) {
  const auto list = devices({"llvmpipe"});
  try {
    backends::vulkan::chooseDevice(list, "2");
    FAIL() << "index 2 of one device was accepted";
  } catch (const NotSupportedError& e) {
    EXPECT_NE(std::string(e.what()).find("[0] llvmpipe"), std::string::npos) << e.what();
  }
  EXPECT_THROW(backends::vulkan::chooseDevice(list, "radeon"), NotSupportedError);
  EXPECT_THROW(backends::vulkan::chooseDevice({}, ""), NotSupportedError);
}

// Timestamps count modulo 2^timestampValidBits; the interval between two is
// their difference in that modulus, in timestampPeriod nanoseconds per tick.
TEST(VulkanTimestamps, IntervalIsTheDifferenceModuloTheValidBitsTimesThePeriod) {
  using backends::vulkan::timestampIntervalMilliseconds;
  EXPECT_DOUBLE_EQ(timestampIntervalMilliseconds(1'000, 3'501'000, 64, 1.0f), 3.5);
  EXPECT_DOUBLE_EQ(timestampIntervalMilliseconds(10, 20, 64, 2.5f), 25e-6);
  // A 36-bit counter that wrapped between the two writes.
  const std::uint64_t top = (std::uint64_t(1) << 36) - 1;
  EXPECT_DOUBLE_EQ(timestampIntervalMilliseconds(top - 99, 900, 36, 1.0f), 1'000e-6);
  // Bits above the valid ones are not part of the count.
  EXPECT_DOUBLE_EQ(timestampIntervalMilliseconds(std::uint64_t(7) << 40 | 100, 300, 36, 1.0f), 200e-6);
  // A full 64-bit counter wraps at 2^64.
  EXPECT_DOUBLE_EQ(timestampIntervalMilliseconds(~std::uint64_t(0), 999'999, 64, 1.0f), 1.0);
}

// A backend on the first device with validation on, or a skip.
std::unique_ptr<backends::Backend> createOrSkip(backends::BackendOptions options = {}) {
  options.validation = true;
  try {
    return backends::findBuiltBackendEntry("vulkan")->create(options);
  } catch (const NotSupportedError& e) {
    return nullptr;
  }
}

TEST(VulkanValidation, AnInvalidCallFailsWithTheLayersMessage) {
  try {
    backends::vulkan::VulkanInstance instance(true);
    if (!instance.validationLog()) GTEST_SKIP() << "VK_LAYER_KHRONOS_validation is not installed";
    backends::vulkan::VulkanDevice device(instance, "");
    // Anisotropic filtering without enabling the samplerAnisotropy feature:
    // a validation error that every driver survives.
    const vk::SamplerCreateInfo invalid{.anisotropyEnable = VK_TRUE, .maxAnisotropy = 2.0f};
    { vk::raii::Sampler sampler(device.device, invalid); }
    try {
      instance.validationLog()->throwIfAny("creating a sampler");
      FAIL() << "the layer said nothing about an invalid sampler";
    } catch (const backends::DriverError& e) {
      EXPECT_NE(std::string(e.what()).find("anisotropy"), std::string::npos) << e.what();
    }
  } catch (const NotSupportedError& e) {
    GTEST_SKIP() << e.what();
  }
}

// A white floor lit straight down by a directional light of intensity 1 fills
// exactly the top-left quadrant of an orthographic view: value 1 there, 0
// elsewhere (hand derivation: albedo 1 * finalColor 1 * saturate(N.L = 1)).
constexpr const char* kQuadrantScene = R"({
  "lightcts": 1, "name": "quadrant", "image": {"width": 16, "height": 8},
  "camera": {"position": [0, 10, 0], "target": [0, 0, 0], "up": [0, 0, -1],
             "projection": "orthographic", "height": 8, "near": 0.1, "far": 100},
  "objects": [{"name": "floor", "mesh": {"type": "plane", "size": [8, 4]},
               "transform": {"translate": [-4, 0, -2]}, "material": {"albedo": [1, 1, 1]}}],
  "lights": [{"name": "sun", "type": "directional", "direction": [0, -1, 0], "color": [1, 1, 1], "intensity": 1}]
})";

TEST(VulkanReadback, RowZeroIsTheTopAndColumnZeroTheLeft) {
  auto backend = createOrSkip();
  if (!backend) GTEST_SKIP() << "no Vulkan device";
  const auto prepared = baking::prepareBakedScene(scene_input::loadSceneText(kQuadrantScene, "quadrant.json"));
  const imaging::Image image = backend->render(lighting::prepareFrame(prepared, 0));
  ASSERT_EQ(image.width, 16);
  ASSERT_EQ(image.height, 8);
  ASSERT_EQ(image.channels, 4);
  // The camera's up is -Z, so the floor's -Z half is the top of the image and
  // its -X half the left; pixel centres keep half a pixel from the edges.
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 16; ++x) {
      const float expected = (x < 8 && y < 4) ? 1.0f : 0.0f;
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(image.at(x, y, c), expected, 1e-6) << "pixel (" << x << ", " << y << ")";
      EXPECT_EQ(image.at(x, y, 3), 1.0f) << "alpha of (" << x << ", " << y << ")";
    }
}

// The full pipeline (every feature on, decided at run time from the
// uniforms) passes every suite scene's own comparison, every frame, against
// the reference and tolerance the specialised pipeline of the scene's test
// (<group>.<name>.vulkan) is held to, so both draw the model within the
// same bounds. The drivers' known mismatches are the scene test's too.
TEST(VulkanSpecialisation, FullShaderPassesEverySceneAsTheSpecialisedDoes) {
  backends::BackendOptions fullOptions;
  fullOptions.variant.specialised = false;
  auto full = createOrSkip(fullOptions);
  if (!full) GTEST_SKIP() << "no Vulkan device";
  const runner::ExpectedFailures expectedFailures =
      backends::testing::suiteExpectedFailures(LIGHTCTS_EXPECTED_FAILURES_DIR);
  int scenes = 0;
  for (const conformance::SceneFile& file : conformance::findSceneFiles(LIGHTCTS_SCENES_DIR)) {
    conformance::SceneReferences references =
        backends::testing::cachedSceneReferences(file.path, scene_input::loadSceneFile(file.path.string()));
    const conformance::SceneCheck check = conformance::checkScene(references, *full);
    ++scenes;
    const std::string test = file.caseName() + ".vulkan";
    if (expectedFailures.find(test)) continue;
    EXPECT_EQ(check.verdict, comparison::Verdict::Pass)
        << test << " with the full shader: " << check.evidence().comparison.failingPixels
        << " failing pixels, tightness " << check.evidence().comparison.maxErrorOverTolerance;
  }
  EXPECT_GE(scenes, 15);
}

}  // namespace

namespace vulkan_driver_choice {

// chromium's SwiftShader, named with --driver: its devices only, never the
// loader's own (lavapipe), and the loader's choice comes back afterwards in
// the same process.
TEST(VulkanDriverChoice, SwiftShaderRunsOnSwiftShaderAlone) {
  backends::BackendOptions options;
  options.driver = "swiftshader";
  std::vector<backends::DeviceInfo> listed;
  try {
    listed = backends::findBuiltBackendEntry("vulkan")->listDevices(options);
  } catch (const backends::NotSupportedError& e) {
    GTEST_SKIP() << e.what();
  }
  ASSERT_FALSE(listed.empty());
  for (const backends::DeviceInfo& d : listed) {
    EXPECT_NE(d.name.find("SwiftShader"), std::string::npos) << d.name;
    EXPECT_EQ(d.selectedBy.rfind("--driver swiftshader --device ", 0), 0u) << d.selectedBy;
    EXPECT_GE(d.subPixelPrecisionBits, 4);
  }
  // The loader's own choice in the same process: no SwiftShader device, so
  // the manifest was the instance's alone.
  const std::vector<backends::DeviceInfo> own = backends::findBuiltBackendEntry("vulkan")->listDevices({});
  for (const backends::DeviceInfo& d : own) EXPECT_EQ(d.name.find("SwiftShader"), std::string::npos) << d.name;
}

TEST(VulkanDriverChoice, AnUnknownDriverIsNotSupportedAndNamesTheKnownOnes) {
  backends::BackendOptions options;
  options.driver = "softpipe";
  try {
    backends::findBuiltBackendEntry("vulkan")->listDevices(options);
    FAIL() << "Vulkan accepted --driver softpipe";
  } catch (const backends::NotSupportedError& e) {
    EXPECT_NE(std::string(e.what()).find("swiftshader"), std::string::npos) << e.what();
  }
}

}  // namespace vulkan_driver_choice
