#include "runner/backend_combination.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace runner {
namespace {

std::vector<std::string> suffixes(const std::vector<BackendCombination>& combinations) {
  std::vector<std::string> names;
  for (const auto& c : combinations) names.push_back(c.suffix);
  return names;
}

TEST(BackendCombination, NoNameMeansAllSevenInTableOrder) {
  EXPECT_EQ(suffixes(selectCombinations({})),
            (std::vector<std::string>{"vulkan", "gl-egl", "gl-osmesa", "gl-egl-softpipe", "gl-osmesa-softpipe",
                                      "vulkan-swiftshader", "gl-egl-zink"}));
}

TEST(BackendCombination, VulkanNamesTheLoadersOwnDriverAlone) {
  // A vendor's `--backend vulkan` with VK_ICD_FILENAMES runs their driver,
  // not chromium's SwiftShader beside it.
  EXPECT_EQ(suffixes(selectCombinations({"vulkan"})), (std::vector<std::string>{"vulkan"}));
  EXPECT_EQ(suffixes(selectCombinations({"vulkan-swiftshader"})), (std::vector<std::string>{"vulkan-swiftshader"}));
  const auto viaDriver = selectCombinations({"vulkan"}, "swiftshader");
  ASSERT_EQ(suffixes(viaDriver), (std::vector<std::string>{"vulkan-swiftshader"}));
  EXPECT_EQ(viaDriver[0].backend, "vulkan");
  EXPECT_EQ(viaDriver[0].driver, "swiftshader");
  // A Vulkan driver's name moves no GL combination.
  EXPECT_EQ(suffixes(selectCombinations({"vulkan", "gl-egl"}, "swiftshader")),
            (std::vector<std::string>{"vulkan-swiftshader", "gl-egl", "gl-egl-softpipe", "gl-egl-zink"}));
  EXPECT_THROW(selectCombinations({"gl-egl"}, "swiftshader"), std::invalid_argument);
}

TEST(BackendCombination, ApiNameStandsForEveryDriverOfIt) {
  EXPECT_EQ(suffixes(selectCombinations({"gl-egl"})),
            (std::vector<std::string>{"gl-egl", "gl-egl-softpipe", "gl-egl-zink"}));
}

TEST(BackendCombination, SuffixPicksOneCombinationWithItsDriver) {
  const auto selected = selectCombinations({"gl-osmesa-softpipe", "vulkan", "vulkan"});
  ASSERT_EQ(suffixes(selected), (std::vector<std::string>{"vulkan", "gl-osmesa-softpipe"}));
  EXPECT_EQ(selected[1].backend, "gl-osmesa");
  EXPECT_EQ(selected[1].driver, "softpipe");
  EXPECT_EQ(selected[0].driver, "");
}

TEST(BackendCombination, UnknownNameIsNamedInTheError) {
  try {
    selectCombinations({"vulkan", "metal"});
    FAIL() << "metal was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'metal'"), std::string::npos) << e.what();
  }
}

TEST(BackendCombination, DriverMakesTheGlCombinationsOnePerApiBackend) {
  // The Vulkan combinations keep their own drivers.
  EXPECT_EQ(suffixes(selectCombinations({}, "softpipe")),
            (std::vector<std::string>{"vulkan", "gl-egl-softpipe", "gl-osmesa-softpipe", "vulkan-swiftshader"}));
  EXPECT_EQ(suffixes(selectCombinations({"gl-egl"}, "llvmpipe")), (std::vector<std::string>{"gl-egl"}));
  // A pair the table does not list keeps its driver's name in the suffix;
  // one it lists is the table's (gl-egl-zink).
  const auto zink = selectCombinations({"gl-osmesa"}, "zink");
  ASSERT_EQ(suffixes(zink), (std::vector<std::string>{"gl-osmesa-zink"}));
  EXPECT_EQ(zink[0].backend, "gl-osmesa");
  EXPECT_EQ(zink[0].driver, "zink");
  EXPECT_EQ(suffixes(selectCombinations({}, "zink")),
            (std::vector<std::string>{"vulkan", "gl-egl-zink", "gl-osmesa-zink", "vulkan-swiftshader"}));
  EXPECT_EQ(suffixes(selectCombinations({"gl-egl-zink"})), (std::vector<std::string>{"gl-egl-zink"}));
  EXPECT_THROW(selectCombinations({"vulkan"}, "softpipe"), std::invalid_argument);
  // A combination that names its own driver may not be given another.
  EXPECT_THROW(selectCombinations({"gl-egl-softpipe"}, "llvmpipe"), std::invalid_argument);
  EXPECT_EQ(suffixes(selectCombinations({"gl-egl-softpipe"}, "softpipe")),
            (std::vector<std::string>{"gl-egl-softpipe"}));
}

}  // namespace
}  // namespace runner
