#include "runner/run_progress.h"

#include <gtest/gtest.h>

#include <sstream>

namespace runner {
namespace {

int countOf(const std::string& text, const std::string& what) {
  int n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// Not a terminal: a plain line at every tenth of a combination's tests.
TEST(RunProgress, PlainLinesAtEveryTenth) {
  std::ostringstream out;
  RunProgress progress(out, false, {"vulkan", "gl-egl"}, {20, 5});
  for (int i = 0; i < 20; ++i) progress.taskDone(0, i == 3);
  const std::string text = out.str();
  EXPECT_EQ(countOf(text, "run: vulkan: "), 10) << text;
  EXPECT_EQ(countOf(text, "\x1b["), 0) << "no terminal codes in a log";
  EXPECT_NE(text.find("run: vulkan: 2/20 tests, 0 failed"), std::string::npos) << text;
  EXPECT_NE(text.find("run: vulkan: 20/20 tests, 1 failed"), std::string::npos) << text;
  EXPECT_NE(text.find(", done"), std::string::npos) << text;
  EXPECT_EQ(countOf(text, "gl-egl"), 0) << "a combination that has not started prints nothing";
  progress.tasksSkipped(1, 5);
  EXPECT_NE(out.str().find("run: gl-egl: 5/5 tests, 0 failed"), std::string::npos) << out.str();
}

TEST(RunProgress, EstimatesTheTimeLeft) {
  std::ostringstream out;
  RunProgress progress(out, false, {"vulkan"}, {10});
  progress.taskDone(0, false);
  EXPECT_NE(progress.line(0).find("left"), std::string::npos) << progress.line(0);
}

// A terminal: the lines are redrawn in place, and a note goes above them.
TEST(RunProgress, TerminalRedrawsInPlace) {
  std::ostringstream out;
  RunProgress progress(out, true, {"vulkan"}, {2});
  progress.taskDone(0, false);
  progress.note("  Crash some.test.vulkan");
  progress.taskDone(0, false);
  const std::string text = out.str();
  EXPECT_GT(countOf(text, "\x1b[1A"), 0) << "moves up over the drawn lines";
  EXPECT_NE(text.find("  Crash some.test.vulkan\n"), std::string::npos);
  EXPECT_NE(text.rfind("run: vulkan: 2/2 tests"), std::string::npos);
}

}  // namespace
}  // namespace runner
