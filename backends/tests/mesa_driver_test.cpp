// Which GL_RENDERER strings count as the Mesa driver asked for, and the
// Vulkan driver pinned under zink (backends/gl/gl_context.h). The renderer
// strings are written out by hand: Mesa 22.3.6's on Debian 12, and zink's
// form of later Mesa releases.
#include "backends/gl/gl_context.h"
#include "backends/vulkan/vulkan_drivers.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace backends::gl {
namespace {

constexpr const char* kLlvmpipe = "llvmpipe (LLVM 15.0.6, 256 bits)";
constexpr const char* kZinkOnLavapipe = "zink (llvmpipe (LLVM 15.0.6, 256 bits))";
constexpr const char* kLaterZinkOnLavapipe = "zink Vulkan 1.3(llvmpipe (LLVM 15.0.7, 256 bits) (MESA_LLVMPIPE))";

TEST(MesaDriver, RendererNamesTheDriverAsAWord) {
  EXPECT_TRUE(rendererRunsOn(kLlvmpipe, "llvmpipe"));
  EXPECT_TRUE(rendererRunsOn("softpipe", "softpipe"));
  EXPECT_FALSE(rendererRunsOn(kLlvmpipe, "softpipe"));
  EXPECT_FALSE(rendererRunsOn("llvmpipex", "llvmpipe"));
}

TEST(MesaDriver, ZinkCountsOnlyOverLavapipe) {
  EXPECT_TRUE(rendererRunsOn(kZinkOnLavapipe, "zink"));
  EXPECT_TRUE(rendererRunsOn(kLaterZinkOnLavapipe, "zink"));
  // zink over llvmpipe is not llvmpipe.
  EXPECT_FALSE(rendererRunsOn(kZinkOnLavapipe, "llvmpipe"));
  // zink over any other Vulkan driver is not the zink the suite asks for.
  EXPECT_FALSE(rendererRunsOn("zink (AMD Radeon RX 6800 (RADV NAVI21))", "zink"));
  EXPECT_FALSE(rendererRunsOn("zink Vulkan 1.3(SwiftShader Device (Subzero) (GOOGLE_SWIFTSHADER))", "zink"));
  // A fallback to llvmpipe itself is not zink.
  EXPECT_FALSE(rendererRunsOn(kLlvmpipe, "zink"));
  EXPECT_EQ(describeMesaDriver("zink"), "zink on lavapipe");
  EXPECT_EQ(describeMesaDriver("softpipe"), "softpipe");
}

std::string variable(const char* name) {
  const char* value = std::getenv(name);
  return value ? value : "(unset)";
}

TEST(MesaDriver, ZinkIsPinnedToLavapipesManifestWhileThePinLives) {
  EXPECT_EQ(pinVulkanDriverUnder("llvmpipe"), nullptr);
  EXPECT_EQ(pinVulkanDriverUnder("softpipe"), nullptr);
  const std::string manifest = vulkan::lavapipeDriver().manifest;
  if (!std::filesystem::exists(manifest)) {
    EXPECT_THROW(pinVulkanDriverUnder("zink"), NotSupportedError);
    GTEST_SKIP() << manifest << " is not installed";
  }
  ::setenv("VK_ICD_FILENAMES", "/vendor/icd.json", 1);
  ::unsetenv("VK_DRIVER_FILES");
  ::unsetenv("NODEVICE_SELECT");
  {
    const auto pin = pinVulkanDriverUnder("zink");
    ASSERT_NE(pin, nullptr);
    EXPECT_EQ(variable("VK_DRIVER_FILES"), manifest);
    EXPECT_EQ(variable("VK_ICD_FILENAMES"), manifest);
    EXPECT_EQ(variable("NODEVICE_SELECT"), "1");
  }
  EXPECT_EQ(variable("VK_ICD_FILENAMES"), "/vendor/icd.json");
  EXPECT_EQ(variable("VK_DRIVER_FILES"), "(unset)");
  EXPECT_EQ(variable("NODEVICE_SELECT"), "(unset)");
  ::unsetenv("VK_ICD_FILENAMES");
}

}  // namespace
}  // namespace backends::gl
