#include "reports/html_report.h"
#include "reports/image_links.h"
#include "reports/tests/sample_results.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

namespace reports {
namespace {

namespace fs = std::filesystem;

long long occurrences(const std::string& text, const std::string& what) {
  long long n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

std::string sampleHtml() { return htmlReport(testing::records(testing::sampleResults()), "/runs/r1", "/runs/r1/report"); }

std::set<std::string> imageSources(const std::string& html) {
  std::set<std::string> sources;
  const std::regex img("<img (?:class=\"thumb\" )?src=\"([^\"]*)\"");
  for (auto it = std::sregex_iterator(html.begin(), html.end(), img); it != std::sregex_iterator(); ++it)
    sources.insert((*it)[1].str());
  return sources;
}

TEST(HtmlReport, HasEverySection) {
  const std::string html = sampleHtml();
  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  for (const char* id : {"backends", "mutants", "attention", "tests", "popping", "slowest"})
    EXPECT_NE(html.find(std::string("<h2 id=\"") + id + "\""), std::string::npos) << id;
  EXPECT_NE(html.find("<strong>5 failing tests, 2 mutant runs not killed, 0 backends with an error</strong>"),
            std::string::npos);
  EXPECT_NE(html.find("v0.1-42-gabc1234"), std::string::npos);
  EXPECT_NE(html.find("2026-11-25T10:00:00Z"), std::string::npos);
  EXPECT_NE(html.find("93.25 s"), std::string::npos);
  EXPECT_NE(html.find("llvmpipe (LLVM 15.0.6, 256 bits)"), std::string::npos);
  EXPECT_NE(html.find("Mesa 22.3.6"), std::string::npos);
  EXPECT_NE(html.find("Tests that need attention (6)"), std::string::npos);  // Fail x2, QW, Crash, Timeout, UP
  EXPECT_NE(html.find("All tests (10)"), std::string::npos);
  EXPECT_EQ(occurrences(html, "<section class=\"test "), 6);
  const std::size_t popping = html.find("<h3>limits.popping-64</h3>");  // the popping table
  ASSERT_NE(popping, std::string::npos);
  const std::string table = html.substr(popping, html.find("</table>", popping) - popping);
  EXPECT_NE(table.find("<th colspan=\"3\">vulkan</th><th colspan=\"3\">gl-egl-softpipe</th>"), std::string::npos)
      << "the timed-out test of the animated scene has a column too";
  EXPECT_EQ(occurrences(table, "<tr><td class=\"n\">"), 3) << "one row per frame";
  EXPECT_NE(table.find("<td class=\"n\">0.5</td><td class=\"n\">0.4</td>"), std::string::npos);
  EXPECT_NE(html.find("by attenuation.point-d-half-range, attenuation.point-d-0-8-range"), std::string::npos);
  EXPECT_NE(html.find("<span class=\"v v-survived\">survived</span>"), std::string::npos);
  EXPECT_NE(html.find("[0.249, 0.251]"), std::string::npos) << "reference +- tolerance";
  EXPECT_NE(html.find("[0.498, 0.502]"), std::string::npos) << "the pixel's tolerance_scale applies";
  EXPECT_NE(html.find("<td>(non-finite, 0.5, 0.5)</td>"), std::string::npos);
  EXPECT_NE(html.find("<dt>max error</dt><dd>non-finite</dd>"), std::string::npos);
}

TEST(HtmlReport, ImagesAreRelativeToTheReportFolder) {
  const std::string html = sampleHtml();
  const std::set<std::string> expected = {
      "../evidence/attenuation.point-d-half-range.vulkan/result.png",
      "../evidence/attenuation.point-d-half-range.vulkan/reference.png",
      "../evidence/attenuation.point-d-half-range.vulkan/error-mask.png",
      "../evidence/per-object.eleven%20lights%231.gl-egl-softpipe/result.png",
      "../evidence/per-object.eleven%20lights%231.gl-egl-softpipe/reference.png",
      "../evidence/per-object.eleven%20lights%231.gl-egl-softpipe/error-mask.png",
      "../mutants/unsquared-range.vulkan/error-mask.png",
      "../mutants/unsquared-range.gl-egl-softpipe/error-mask.png",
  };
  EXPECT_EQ(imageSources(html), expected);
  EXPECT_EQ(occurrences(html, "<img "), 8);
  EXPECT_NE(html.find("<a href=\"../mutants/unsquared-range.vulkan/error-mask.png\">error mask</a>"),
            std::string::npos);
  EXPECT_NE(html.find("libOSMesa.so.8 not found <a href=\"../logs/gl-osmesa.log\">log</a>"), std::string::npos);
}

TEST(HtmlReport, HeaderCountsSkipsAndExpectedFailuresApart) {
  // The sample has one ExpectedFail and one NotSupported test (gl-egl-softpipe).
  const std::string html = sampleHtml();
  EXPECT_NE(html.find("(10 tests, 1 quality warnings, 1 skipped (not supported), 1 expected failures)"),
            std::string::npos);
  EXPECT_EQ(html.find("skipped or expected failures"), std::string::npos);
}

TEST(HtmlReport, SaysHowTheRunWasChosenAndCheckedAndShowsTheViewer) {
  auto results = testing::sampleResults();
  results["selection"] = {{"include", {"attenuation.*"}}, {"exclude", {"*softpipe*"}}, {"caselists", {"vendor.txt"}}};
  results["baseline_files"] = {{{"kind", "caselist"}, {"path", "vendor.txt"}, {"sha256", "0123abcd"}}};
  results["mutant_check"] = "killers";
  results["mutants_not_checked"] = {{{"mutant", "shadow-fade-ignored"}, {"reason", "none of its killers is selected"}}};
  results["mutants"][2]["killers"] = {"attenuation.point-5mm-above-floor"};  // distance-clamp-1e-4 on vulkan
  results["mutants"][2]["status"] = "survived";
  results["tests"][1]["evidence"]["images_kept"] = false;
  results["evidence_limit"] = 50;
  const std::string html = htmlReport(testing::records(results), "/runs/r1", "/runs/r1/report");
  EXPECT_NE(html.find("--include attenuation.* --exclude *softpipe* --caselist vendor.txt"), std::string::npos);
  EXPECT_NE(html.find("vendor.txt (SHA-256 0123abcd)"), std::string::npos);
  EXPECT_NE(html.find("This run checked each mutant against its killers"), std::string::npos);
  EXPECT_NE(html.find("missed by its killers: attenuation.point-5mm-above-floor"), std::string::npos);
  EXPECT_NE(html.find("<li>shadow-fade-ignored: none of its killers is selected</li>"), std::string::npos);
  EXPECT_NE(html.find("<iframe class=\"viewer\" src=\"../evidence/attenuation.point-d-half-range.vulkan/viewer.html\""),
            std::string::npos);
  EXPECT_NE(html.find("No images: this failure came after the first --evidence-limit 50"), std::string::npos);

  results["mutant_check"] = "all-scenes";
  EXPECT_NE(htmlReport(testing::records(results), "/runs/r1", "/runs/r1/report").find("against every selected scene (the whole kill table)"),
            std::string::npos);
}

TEST(HtmlReport, IsSelfContained) {
  const std::string html = sampleHtml();
  EXPECT_EQ(html.find("<script"), std::string::npos);
  EXPECT_EQ(html.find("http://"), std::string::npos);
  EXPECT_EQ(html.find("https://"), std::string::npos);
  EXPECT_EQ(html.find("<link"), std::string::npos);
  EXPECT_NE(html.find("<style>"), std::string::npos);
}

TEST(HtmlReport, EscapesAllText) {
  const std::string html = sampleHtml();
  EXPECT_NE(html.find("d &lt; r &amp; &quot;half&quot; range"), std::string::npos);
  EXPECT_NE(html.find("signal 11 &lt;SIGSEGV&gt; &amp; &quot;core&quot;"), std::string::npos);
  EXPECT_NE(html.find("Test CPU &lt;8 cores&gt;"), std::string::npos);
  EXPECT_EQ(html.find("<SIGSEGV>"), std::string::npos);
  EXPECT_EQ(html.find("<8 cores>"), std::string::npos);
  EXPECT_EQ(html.find("<not 1e-6>"), std::string::npos);
  EXPECT_EQ(html.find("\"half\""), std::string::npos);
}

TEST(HtmlReport, LinksFromAnyReportFolder) {
  EXPECT_EQ(imageHref("evidence/a/result.png", "/x/run", "/x/run/report"), "../evidence/a/result.png");
  EXPECT_EQ(imageHref("evidence/a/result.png", "/x/run/", "/x/run/report/"), "../evidence/a/result.png");
  EXPECT_EQ(imageHref("evidence/a/result.png", "/x/run", "/x/pages/report"), "../../run/evidence/a/result.png");
  EXPECT_EQ(imageHref("./evidence/../e/r.png", "/x/run", "/x/run"), "e/r.png");
  EXPECT_EQ(imageHref("/abs/r.png", "/x/run", "/x/run/report"), "../../../abs/r.png");
  EXPECT_EQ(imageHref("", "/x/run", "/x/run/report"), "");
  const fs::path cwd = fs::current_path();
  EXPECT_EQ(imageHref("e/r.png", "out/run", cwd / "out/run/report"), "../e/r.png");
}

TEST(HtmlReport, WritesIndexHtmlInTheReportFolderAndMarksMissingImages) {
  const fs::path run = fs::path(::testing::TempDir()) / "reports_html_test";
  fs::remove_all(run);
  writeHtmlReport(testing::records(testing::sampleResults()), run / "report");
  std::ifstream file(run / "report" / "index.html");
  std::stringstream text;
  text << file.rdbuf();
  EXPECT_EQ(text.str(), htmlReport(testing::records(testing::sampleResults()), run, run / "report"));
  EXPECT_EQ(occurrences(text.str(), "(missing when the report was written)"), 6);  // evidence figures
  long long entries = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(run / "report")) ++entries;
  EXPECT_EQ(entries, 1) << "no temporary file is left behind";
  fs::remove_all(run);
}

// results.json is not trusted: a verdict the report does not know is a
// failing test with a section of its own, never a pass.
TEST(HtmlReport, UnknownVerdictIsAFailureThatNeedsAttention) {
  auto results = testing::sampleResults();
  results["tests"][0]["verdict"] = "Maybe";
  const std::string html = htmlReport(testing::records(results), "/runs/r1", "/runs/r1/report");
  EXPECT_NE(html.find("<strong>6 failing tests, 2 mutant runs not killed, 0 backends with an error</strong>"),
            std::string::npos);
  EXPECT_NE(html.find("Tests that need attention (7)"), std::string::npos);
  EXPECT_NE(html.find("<span class=\"v v-unknown\">Maybe</span>"), std::string::npos);
}

// The backend table has a Flake column only when a flake occurred, so the
// report of a run without retries has the six verdict columns of
// results.json's version 1.
TEST(HtmlReport, FlakeColumnOnlyWhenAFlakeOccurred) {
  EXPECT_EQ(sampleHtml().find("<th>Flake</th>"), std::string::npos);
  EXPECT_NE(sampleHtml().find("<th>UnexpectedPass</th><th>wall s</th>"), std::string::npos);
  auto results = testing::sampleResults();
  results["tests"][0]["verdict"] = "Flake";
  const std::string html = htmlReport(testing::records(results), "/runs/r1", "/runs/r1/report");
  EXPECT_NE(html.find("<th>UnexpectedPass</th><th>Flake</th><th>wall s</th>"), std::string::npos);
  EXPECT_NE(html.find("<strong>5 failing tests,"), std::string::npos) << "a flake passed in the end";
  EXPECT_NE(html.find("Tests that need attention (7)"), std::string::npos) << "but someone should look at it";
}

// The sample the report tests use holds only keys the records read: a key
// the records rename (or drop) leaves the sample with one they no longer
// know, and this test names it.
void expectKeysRead(const nlohmann::ordered_json& sample, const nlohmann::ordered_json& read, const std::string& path) {
  if (sample.is_object()) {
    ASSERT_TRUE(read.is_object()) << path;
    for (const auto& [key, value] : sample.items()) {
      ASSERT_TRUE(read.contains(key)) << path << "/" << key << " is not read by the records";
      expectKeysRead(value, read[key], path + "/" + key);
    }
  } else if (sample.is_array() && read.is_array()) {
    for (std::size_t i = 0; i < sample.size() && i < read.size(); ++i)
      expectKeysRead(sample[i], read[i], path + "/" + std::to_string(i));
  }
}

TEST(HtmlReport, TheSampleHoldsOnlyKeysTheRecordsRead) {
  nlohmann::ordered_json read = testing::sampleRun().toJson();
  read.erase("slowest");  // derived from the tests when written, never read
  expectKeysRead(testing::sampleResults(), read, "");
}

TEST(HtmlReport, ToleratesAnEmptyRun) {
  const std::string html = htmlReport(results::RunRecord{}, "run", "run/report");
  EXPECT_NE(html.find("No mutants in this run."), std::string::npos);
  EXPECT_NE(html.find("No animated scenes in this run."), std::string::npos);
  EXPECT_NE(html.find("Tests that need attention (0)"), std::string::npos);
}

}  // namespace
}  // namespace reports
