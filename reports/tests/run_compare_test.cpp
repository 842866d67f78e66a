// `lightcts run compare`: reports/run_compare.h on hand-written
// results objects.
#include "reports/run_compare.h"
#include "reports/tests/sample_results.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace {

using reports::Json;

Json test(const std::string& name, const std::string& verdict, Json tightness = nullptr) {
  Json entry = {{"name", name}, {"verdict", verdict}};
  if (!tightness.is_null()) entry["metrics"] = {{"tightness", tightness}, {"tightness_is_infinite", false}};
  return entry;
}

Json run(Json tests) { return {{"format", "lightcts-results"}, {"version", 1}, {"tests", std::move(tests)}}; }

std::vector<std::string> names(const auto& rows) {
  std::vector<std::string> out;
  for (const auto& row : rows) out.push_back(row.test);
  return out;
}

TEST(RunCompare, RunAgainstItselfIsUnchanged) {
  const Json r = run({test("a.x.vulkan", "Pass", 0.1), test("a.y.vulkan", "Fail", 3.0),
                      test("a.z.vulkan", "NotSupported")});
  const auto c = reports::compareRuns(reports::testing::records(r), reports::testing::records(r));
  EXPECT_TRUE(c.unchanged());
  EXPECT_EQ(c.oldTests, 3u);
  std::ostringstream out;
  reports::printRunComparison(c, "old", "new", out);
  EXPECT_NE(out.str().find("no change"), std::string::npos) << out.str();
}

TEST(RunCompare, PassToFailCrashTimeoutIsARegression) {
  const Json before = run({test("t.fail", "Pass"), test("t.crash", "Pass"), test("t.timeout", "QualityWarning"),
                           test("t.same", "Pass")});
  const Json after = run({test("t.fail", "Fail"), test("t.crash", "Crash"), test("t.timeout", "Timeout"),
                          test("t.same", "Pass")});
  const auto c = reports::compareRuns(reports::testing::records(before), reports::testing::records(after));
  EXPECT_EQ(names(c.regressions), (std::vector<std::string>{"t.fail", "t.crash", "t.timeout"}));
  EXPECT_EQ(c.regressions[0].oldVerdict, "Pass");
  EXPECT_EQ(c.regressions[0].newVerdict, "Fail");
  EXPECT_TRUE(c.fixes.empty());
  EXPECT_FALSE(c.unchanged());
  std::ostringstream out;
  reports::printRunComparison(c, "old", "new", out);
  EXPECT_NE(out.str().find("REGRESSION t.crash: Pass -> Crash"), std::string::npos) << out.str();
  EXPECT_NE(out.str().find("3 regressions"), std::string::npos) << out.str();
}

TEST(RunCompare, FailToPassIsAFix) {
  const auto c = reports::compareRuns(reports::testing::records(run({test("t.a", "Crash"), test("t.b", "Fail")})),
                                      reports::testing::records(run({test("t.a", "Pass"), test("t.b", "ExpectedFail")})));
  EXPECT_TRUE(c.regressions.empty());
  EXPECT_EQ(names(c.fixes), (std::vector<std::string>{"t.a", "t.b"}));
}

TEST(RunCompare, OtherVerdictChangesAreNeitherRegressionsNorFixes) {
  const auto c = reports::compareRuns(reports::testing::records(run({test("t.a", "Pass"), test("t.b", "Fail")})),
                                      reports::testing::records(run({test("t.a", "NotSupported"), test("t.b", "Crash")})));
  EXPECT_TRUE(c.regressions.empty());
  EXPECT_TRUE(c.fixes.empty());
  EXPECT_EQ(names(c.changes), (std::vector<std::string>{"t.a", "t.b"}));
}

TEST(RunCompare, NewAndRemovedTestsByName) {
  const auto c = reports::compareRuns(reports::testing::records(run({test("t.kept", "Pass"), test("t.gone", "Fail")})),
                                      reports::testing::records(run({test("t.added", "Fail"), test("t.kept", "Pass")})));
  ASSERT_EQ(c.added.size(), 1u);
  EXPECT_EQ(c.added[0].test, "t.added");
  EXPECT_EQ(c.added[0].verdict, "Fail");
  ASSERT_EQ(c.removed.size(), 1u);
  EXPECT_EQ(c.removed[0].test, "t.gone");
  EXPECT_TRUE(c.regressions.empty());  // a new failing test is new, not a regression
}

TEST(RunCompare, TightnessBeyondTwiceEitherWay) {
  const Json before = run({test("t.up", "Pass", 0.1), test("t.down", "Pass", 0.4), test("t.twice", "Pass", 0.1),
                           test("t.half", "Pass", 0.2), test("t.small", "Pass", 0.1), test("t.infinite", "Pass", 0.1),
                           test("t.from-zero", "Pass", 0.0), test("t.zeros", "Pass", 0.0)});
  Json after = run({test("t.up", "Pass", 0.25), test("t.down", "Pass", 0.1), test("t.twice", "Pass", 0.2),
                    test("t.half", "Pass", 0.1), test("t.small", "Pass", 0.15), test("t.infinite", "Fail", nullptr),
                    test("t.from-zero", "Pass", 0.01), test("t.zeros", "Pass", 0.0)});
  after["tests"][5]["metrics"] = {{"tightness", nullptr}, {"tightness_is_infinite", true}};
  const auto c = reports::compareRuns(reports::testing::records(before), reports::testing::records(after));
  EXPECT_EQ(names(c.tightness), (std::vector<std::string>{"t.up", "t.down", "t.from-zero"}));
  EXPECT_DOUBLE_EQ(c.tightness[0].oldTightness, 0.1);
  EXPECT_DOUBLE_EQ(c.tightness[0].newTightness, 0.25);
  EXPECT_EQ(names(c.regressions), (std::vector<std::string>{"t.infinite"}));
  std::ostringstream out;
  reports::printRunComparison(c, "old", "new", out);
  EXPECT_NE(out.str().find("tightness t.up: 0.1 -> 0.25 (x2.5)"), std::string::npos) << out.str();
  EXPECT_NE(out.str().find("tightness t.down: 0.4 -> 0.1 (x0.25)"), std::string::npos) << out.str();
}

TEST(RunCompare, UnknownVerdictCountsAsFailure) {
  Json after = run({test("t.a", "pass"), test("t.b", "Pass"), Json{{"name", "t.c"}}});
  const auto c = reports::compareRuns(reports::testing::records(run({test("t.a", "Pass"), test("t.b", "Bogus"), test("t.c", "Pass")})), reports::testing::records(after));
  EXPECT_EQ(names(c.regressions), (std::vector<std::string>{"t.a", "t.c"}));
  EXPECT_EQ(names(c.fixes), (std::vector<std::string>{"t.b"}));
}

// Fields of the wrong type read as their defaults (results/run_records.h):
// a verdict that is no word counts as a failure, a tightness that is no
// number is no tightness; of two tests with one name the first counts.
TEST(RunCompare, MistypedFieldsReadAsTheirDefaults) {
  Json before = run({test("t.a", "Pass"), Json{{"name", "t.b"}, {"verdict", "Pass"}, {"metrics", "oops"}},
                     test("t.a", "Fail")});
  Json after = run({Json{{"name", "t.a"}, {"verdict", Json::array()}},
                    Json{{"name", "t.b"}, {"verdict", "Pass"}, {"metrics", {{"tightness", "big"}}}}});
  const auto c = reports::compareRuns(reports::testing::records(before), reports::testing::records(after));
  EXPECT_EQ(names(c.regressions), (std::vector<std::string>{"t.a"}));
  EXPECT_TRUE(c.removed.empty());
  EXPECT_TRUE(c.tightness.empty());
}

TEST(RunCompare, HtmlPageListsEveryKindEscaped) {
  const Json before = run({test("t.<reg>", "Pass", 0.1), test("t.fix", "Fail"), test("t.gone", "Pass")});
  Json after = run({test("t.<reg>", "Crash", 0.5), test("t.fix", "Pass"), test("t.new", "Pass")});
  after["started_utc"] = "2026-12-02T00:00:00Z";
  const auto c = reports::compareRuns(reports::testing::records(before), reports::testing::records(after));
  const std::string html = reports::runComparisonHtml(c, reports::testing::records(before), reports::testing::records(after), "old/results.json", "new & co/results.json");
  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  for (const char* wanted : {"t.&lt;reg&gt;", "td class=\"v crash\">Crash", "t.fix", "t.new", "t.gone",
                             "new &amp; co/results.json", "2026-12-02T00:00:00Z", "id=\"regressions\"",
                             "Regressions (1)", "Tightness beyond 2x (1)", "x5"})
    EXPECT_NE(html.find(wanted), std::string::npos) << wanted;
  EXPECT_EQ(html.find("t.<reg>"), std::string::npos);
  EXPECT_EQ(html.find("no change"), std::string::npos);

  const auto dir = std::filesystem::temp_directory_path() / ("run-compare-test-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  const auto file = reports::writeRunComparisonHtml(c, reports::testing::records(before), reports::testing::records(after), "old", "new", dir / "page");
  EXPECT_EQ(file, dir / "page" / "index.html");
  std::ifstream in(file);
  std::stringstream written;
  written << in.rdbuf();
  EXPECT_NE(written.str().find("Regressions (1)"), std::string::npos);
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(dir / "page")) ++entries;
  EXPECT_EQ(entries, 1u);  // no temporary left behind
  std::filesystem::remove_all(dir);
}

TEST(RunCompare, UnchangedPageSaysNoChange) {
  const Json r = run({test("t.a", "Pass")});
  const std::string html = reports::runComparisonHtml(reports::compareRuns(reports::testing::records(r), reports::testing::records(r)), reports::testing::records(r), reports::testing::records(r), "a", "b");
  EXPECT_NE(html.find("no change"), std::string::npos);
}

}  // namespace
