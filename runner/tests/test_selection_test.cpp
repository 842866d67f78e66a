#include "runner/test_selection.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace runner {
namespace {

const std::vector<std::string> kNames = {
    "shadows.hard.vulkan",          "shadows.hard.gl-egl",        "shadows.hard.gl-egl-softpipe",
    "shadows.tent.gl-osmesa",       "shadows.tent.gl-osmesa-softpipe", "limits.sixty-five.vulkan",
    "attenuation.point-d-0.gl-egl",
};

std::vector<std::string> chosen(const TestSelection& selection) {
  const std::vector<bool> pick = selection.select(kNames);
  std::vector<std::string> names;
  for (std::size_t i = 0; i < kNames.size(); ++i)
    if (pick[i]) names.push_back(kNames[i]);
  return names;
}

TEST(TestSelection, NothingGivenSelectsEverything) {
  TestSelection none;
  EXPECT_FALSE(none.narrows());
  EXPECT_EQ(chosen(none), kNames);
}

TEST(TestSelection, IncludeThenExclude) {
  TestSelection s;
  s.include("shadows.*");
  s.exclude("*softpipe*");
  EXPECT_EQ(chosen(s), (std::vector<std::string>{"shadows.hard.vulkan", "shadows.hard.gl-egl",
                                                 "shadows.tent.gl-osmesa"}));
}

TEST(TestSelection, IncludesAreAUnionAndGlobsAreShellStyle) {
  TestSelection s;
  s.include("limits.*");
  s.include("attenuation.point-d-[0-9].gl-egl");
  s.include("shadows.????.vulkan");
  EXPECT_EQ(chosen(s), (std::vector<std::string>{"shadows.hard.vulkan", "limits.sixty-five.vulkan",
                                                 "attenuation.point-d-0.gl-egl"}));
}

TEST(TestSelection, CaselistWithCommentsIsTheSameAsTheGlobs) {
  TestSelection s;
  s.parseCaselist("# the shadows, no softpipe\n\nshadows.hard.vulkan\nshadows.hard.gl-egl  # a comment\r\n"
                  "  shadows.tent.gl-osmesa\n",
                  "list.txt");
  EXPECT_EQ(chosen(s), (std::vector<std::string>{"shadows.hard.vulkan", "shadows.hard.gl-egl",
                                                 "shadows.tent.gl-osmesa"}));
}

TEST(TestSelection, CaselistAndIncludeIntersect) {
  TestSelection s;
  s.parseCaselist("shadows.*\n", "list.txt");
  s.include("*.vulkan");
  EXPECT_EQ(chosen(s), (std::vector<std::string>{"shadows.hard.vulkan"}));
}

TEST(TestSelection, ALineThatMatchesNothingIsNamedWithItsLine) {
  TestSelection s;
  s.parseCaselist("# first line a comment\nshadows.hard.vulkan\nshadows.no-such-test.vulkan\n", "vendor.txt");
  try {
    s.select(kNames);
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("vendor.txt:3"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("shadows.no-such-test.vulkan"), std::string::npos) << e.what();
  }
}

TEST(TestSelection, AnIncludeThatMatchesNothingIsAnError) {
  TestSelection s;
  s.include("shadow.*");  // the group is "shadows"
  EXPECT_THROW(s.select(kNames), std::invalid_argument);
}

TEST(TestSelection, ASelectionThatLeavesNothingIsAnError) {
  TestSelection s;
  s.include("shadows.*");
  s.exclude("shadows.*");
  EXPECT_THROW(s.select(kNames), std::invalid_argument);
}

TEST(TestSelection, ACaselistLineHoldsOneName) {
  TestSelection s;
  EXPECT_THROW(s.parseCaselist("shadows.hard.vulkan shadows.hard.gl-egl\n", "l.txt"), std::invalid_argument);
  EXPECT_THROW(s.parseCaselist("# only comments\n\n", "l.txt"), std::invalid_argument);
  EXPECT_THROW(s.loadCaselist("/nonexistent/caselist.txt"), std::invalid_argument);
}

}  // namespace
}  // namespace runner
