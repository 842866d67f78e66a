// The one table of backend combinations (backends/backend_combinations.def)
// as C++ reads it and as CMake reads it (backends/backend_combinations.cmake,
// which names ctest's tests and labels): two parsers of one file, which must
// agree, and the seven combinations written out by hand.
#include "backends/backend_combinations.h"

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

namespace backends {
namespace {

TEST(CombinationTable, TheSevenInOrder) {
  std::vector<std::string> rows;
  for (const BackendCombination& c : backendCombinations()) rows.push_back(c.suffix + "=" + c.backend + "=" + c.driver);
  EXPECT_EQ(rows, (std::vector<std::string>{"vulkan=vulkan=", "gl-egl=gl-egl=llvmpipe", "gl-osmesa=gl-osmesa=llvmpipe",
                                            "gl-egl-softpipe=gl-egl=softpipe",
                                            "gl-osmesa-softpipe=gl-osmesa=softpipe",
                                            "vulkan-swiftshader=vulkan=swiftshader", "gl-egl-zink=gl-egl=zink"}));
}

TEST(CombinationTable, CMakeReadsTheSameRows) {
  // LIGHTCTS_CMAKE_COMBINATIONS: CMake's list joined with ',', "default" for
  // an empty driver.
  std::vector<std::string> fromCMake;
  std::istringstream list(LIGHTCTS_CMAKE_COMBINATIONS);
  for (std::string item; std::getline(list, item, ',');) fromCMake.push_back(item);
  std::vector<std::string> fromCpp;
  for (const BackendCombination& c : backendCombinations())
    fromCpp.push_back(c.suffix + "=" + c.backend + "=" + (c.driver.empty() ? "default" : c.driver));
  EXPECT_EQ(fromCMake, fromCpp);
}

TEST(CombinationTable, LookUps) {
  ASSERT_NE(findCombination("gl-osmesa-softpipe"), nullptr);
  EXPECT_EQ(findCombination("gl-osmesa-softpipe")->backend, "gl-osmesa");
  // The bench's second paths to a driver: OSMesa beside EGL, for both drivers.
  for (const char* second : {"gl-osmesa", "gl-osmesa-softpipe"}) EXPECT_TRUE(findCombination(second)->isSecondContextPath());
  for (const char* first : {"vulkan", "gl-egl", "gl-egl-softpipe"}) EXPECT_FALSE(findCombination(first)->isSecondContextPath());
  EXPECT_EQ(findCombination("metal"), nullptr);
  // The default driver of a GL backend is llvmpipe; Vulkan's is the loader's
  // own, and SwiftShader is named.
  EXPECT_EQ(findCombination("gl-egl", "")->suffix, "gl-egl");
  EXPECT_EQ(findCombination("gl-egl", "softpipe")->suffix, "gl-egl-softpipe");
  EXPECT_EQ(findCombination("gl-egl", "zink")->suffix, "gl-egl-zink");
  EXPECT_EQ(findCombination("gl-osmesa", "zink"), nullptr);
  // zink draws through lavapipe, which the vulkan combination times.
  EXPECT_TRUE(findCombination("gl-egl-zink")->isSecondContextPath());
  EXPECT_EQ(findCombination("vulkan", "")->suffix, "vulkan");
  EXPECT_EQ(findCombination("vulkan", "softpipe"), nullptr);
  EXPECT_EQ(findCombination("vulkan", "swiftshader")->suffix, "vulkan-swiftshader");
  EXPECT_FALSE(findCombination("vulkan-swiftshader")->takesMesaDriver());
  EXPECT_EQ(vulkanDriverCombination("swiftshader"), findCombination("vulkan-swiftshader"));
  EXPECT_EQ(vulkanDriverCombination("softpipe"), nullptr);
  EXPECT_EQ(vulkanDriverCombination(""), nullptr);
  EXPECT_TRUE(findCombination("gl-osmesa")->takesMesaDriver());
  EXPECT_EQ(findCombination("gl-egl-softpipe")->identifier(), "gl_egl_softpipe");
  EXPECT_EQ(combinationSuffixList(),
            "vulkan, gl-egl, gl-osmesa, gl-egl-softpipe, gl-osmesa-softpipe, vulkan-swiftshader, gl-egl-zink");
}

}  // namespace
}  // namespace backends
