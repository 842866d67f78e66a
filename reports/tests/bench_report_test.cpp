// The benchmark pages of the hand-written bench.json (bench_sample.h).
#include "reports/bench_data.h"
#include "imaging/tests/scratch_folder_test.h"
#include "reports/bench_report.h"
#include "reports/html_page.h"
#include "reports/html_report.h"
#include "reports/tests/bench_sample.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include <unistd.h>

namespace reports {
namespace {

namespace fs = std::filesystem;

long long count(const std::string& text, const std::string& what) {
  long long n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

using imaging::testing::readFile;

// data-point of every point drawn as on the Pareto front.
std::set<std::string> frontPoints(const std::string& html) {
  std::set<std::string> points;
  const std::regex front("<circle class=\"pt front\" data-point=\"([^\"]*)\"");
  for (auto it = std::sregex_iterator(html.begin(), html.end(), front); it != std::sregex_iterator(); ++it)
    points.insert((*it)[1].str());
  return points;
}

const BenchEntry& entry(const BenchSet& set, const std::string& name) {
  for (const BenchEntry& e : set.entries)
    if (e.name.full == name) return e;
  throw std::runtime_error("no benchmark " + name);
}

TEST(BenchData, ParsesNames) {
  const BenchName a = parseBenchName("frame/vulkan/lights64-1280x720/legacy-4+4/manual_time");
  EXPECT_EQ(a.full, "frame/vulkan/lights64-1280x720/legacy-4+4");
  EXPECT_EQ(a.kind, "frame");
  EXPECT_EQ(a.backend, "vulkan");
  EXPECT_EQ(a.scene, "lights64-1280x720");
  EXPECT_EQ(a.mode, "legacy-4+4");
  EXPECT_EQ(a.x, "");
  const BenchName b = parseBenchName("frame/gl-egl/curve-resolution/all-lights/1280x720/repeats:5/real_time");
  EXPECT_EQ(b.full, "frame/gl-egl/curve-resolution/all-lights/1280x720");
  EXPECT_EQ(b.x, "1280x720");
  EXPECT_EQ(curveX(b.x), 921600.0);
  EXPECT_EQ(curveX("64"), 64.0);
  EXPECT_FALSE(curveX("abc").has_value());
  EXPECT_EQ(parseBenchName("BM_Old").kind, "BM_Old");
}

TEST(BenchData, MediansSpreadAndFits) {
  const BenchSet set = readBenchFile(testing::sampleBench());
  const BenchEntry& v = entry(set, "frame/vulkan/lights64-1280x720/all-lights");
  EXPECT_EQ(v.section, "vulkan");
  EXPECT_EQ(v.count, 5);
  EXPECT_TRUE(v.medianFromAggregate);
  EXPECT_DOUBLE_EQ(*v.medianMs, 10.0);
  EXPECT_DOUBLE_EQ(*v.minMs, 9.8);
  EXPECT_DOUBLE_EQ(*v.maxMs, 10.5);
  EXPECT_DOUBLE_EQ(*v.stddevMs, 0.27);
  EXPECT_DOUBLE_EQ(v.counters.at("device_ms"), 10.0);
  // gl-egl: no aggregates, microseconds: the median is computed from the repetitions.
  const BenchEntry& g = entry(set, "frame/gl-egl/lights64-1280x720/all-lights");
  EXPECT_FALSE(g.medianFromAggregate);
  EXPECT_EQ(g.count, 3);
  EXPECT_DOUBLE_EQ(*g.medianMs, 20.0);
  EXPECT_DOUBLE_EQ(*g.minMs, 19.5);
  EXPECT_NEAR(*g.stddevMs, 0.763763, 1e-6);  // sample stddev of 20, 21, 19.5
  EXPECT_FALSE(g.counters.count("device_ms"));
  // Spread: CPU time and CV. The sample's cpu_time is half its real_time.
  EXPECT_DOUBLE_EQ(*v.cpuMedianMs, 5.0);   // the median aggregate's
  EXPECT_DOUBLE_EQ(*v.cv, 0.27 / 10.08);   // stddev / mean aggregates
  EXPECT_DOUBLE_EQ(*g.cpuMedianMs, 10.0);  // median of 10, 10.5, 9.75
  EXPECT_NEAR(*g.cv, 0.763763 / (60.5 / 3), 1e-6);
  // Aggregates only: the count is the aggregate's "repetitions".
  const BenchEntry& p = entry(set, "prepare/cpu/curve-lights/all-lights/1000");
  EXPECT_EQ(p.count, 5);
  EXPECT_DOUBLE_EQ(*p.medianMs, 0.02);
  EXPECT_FALSE(p.minMs.has_value());
  const BenchEntry& withMinMax = entry(set, "prepare/cpu/curve-objects/per-object/1000");  // min, max aggregates
  EXPECT_DOUBLE_EQ(*withMinMax.medianMs, 5e-4);
  EXPECT_DOUBLE_EQ(*withMinMax.minMs, 4.5e-4);
  EXPECT_DOUBLE_EQ(*withMinMax.maxMs, 6e-4);
  const BenchEntry& failed = entry(set, "pipeline/vulkan/attenuation.point-d-zero/all-lights");
  EXPECT_EQ(failed.error, "compile <failed> & \"x\"");
  ASSERT_EQ(set.fits.size(), 2u);
  EXPECT_EQ(set.fits[0].family.full, "prepare/cpu/curve-lights/all-lights");
  EXPECT_EQ(set.fits[0].bigO, "N");
  EXPECT_DOUBLE_EQ(*set.fits[0].coefficientMs, 2e-5);
  EXPECT_DOUBLE_EQ(*set.fits[0].rms, 0.031);
  EXPECT_NEAR(*set.fits[0].at(1000), 0.02, 1e-12);
  EXPECT_EQ(set.fits[1].bigO, "NlgN");
  EXPECT_NEAR(*set.fits[1].at(1024), 0.15e-6 * 1024 * 10, 1e-12);
}

TEST(BenchReport, ParetoFront) {
  // (time, error): (1, 5) fastest; (2, 2); (3, 2) is dominated by (2, 2);
  // (4, 1) most accurate; (5, 5) dominated; two equal points both stay.
  const std::vector<bool> front = paretoFront({{1, 5}, {2, 2}, {3, 2}, {4, 1}, {5, 5}, {2, 2}});
  EXPECT_EQ(front, (std::vector<bool>{true, true, false, true, false, true}));
}

TEST(BenchReport, PageFiles) {
  EXPECT_EQ(benchPageFile("gl-egl-softpipe"), "gl-egl-softpipe.html");
  EXPECT_EQ(benchPageFile("a/b <c>"), "a_b__c_.html");
  EXPECT_EQ(benchPageFile("index"), "backend-index.html");
  EXPECT_EQ(benchBackends(testing::sampleBench()), (std::vector<std::string>{"vulkan", "gl-egl", "gl-osmesa"}));
}

class BenchPages : public imaging::testing::ScratchFolderTest {
 protected:
  BenchPages() : ScratchFolderTest(false) {}  // the report creates its folder
  void SetUp() override {
    ScratchFolderTest::SetUp();
    writeBenchReport(testing::sampleBench(), dir_);
  }
};

TEST_F(BenchPages, WritesEveryPage) {
  std::set<std::string> files;
  for (const auto& f : fs::directory_iterator(dir_)) files.insert(f.path().filename().string());
  EXPECT_EQ(files, (std::set<std::string>{"index.html", "vulkan.html", "gl-egl.html", "gl-osmesa.html"}));
}

TEST_F(BenchPages, OneSvgPerPlot) {
  EXPECT_EQ(count(readFile(dir_ / "index.html"), "<svg "), 7);
  EXPECT_EQ(count(readFile(dir_ / "vulkan.html"), "<svg "), 4);
  EXPECT_EQ(count(readFile(dir_ / "gl-egl.html"), "<svg "), 2);
  EXPECT_EQ(count(readFile(dir_ / "gl-osmesa.html"), "<svg "), 0);
  for (const char* page : {"index.html", "vulkan.html", "gl-egl.html", "gl-osmesa.html"}) {
    const std::string html = readFile(dir_ / page);
    EXPECT_EQ(count(html, "<svg "), count(html, "</svg>")) << page;
    EXPECT_EQ(html.find("<script"), std::string::npos) << page;
    EXPECT_EQ(html.find("<link"), std::string::npos) << page;
    EXPECT_EQ(html.find(" src="), std::string::npos) << page << ": no external resources";
  }
}

TEST_F(BenchPages, ParetoPointsAreTheHandDerivedOnes) {
  const std::string index = readFile(dir_ / "index.html");
  EXPECT_EQ(frontPoints(index),
            (std::set<std::string>{"gl-egl/legacy-4+4", "vulkan/legacy-4+4", "vulkan/per-object",
                                   "vulkan/all-lights", "gl-egl/all-lights"}));
  const std::size_t scatter = index.find("<svg ");
  const std::string firstPlot = index.substr(scatter, index.find("</svg>", scatter) - scatter);
  EXPECT_NE(firstPlot.find("lights64-1280x720: speed against error"), std::string::npos);
  EXPECT_EQ(count(firstPlot, "<circle class=\"pt"), 7) << "one point per (backend, mode)";
  EXPECT_EQ(count(firstPlot, "<line class=\"whisker\""), 7) << "every point has repetitions: a min-max whisker";
  EXPECT_NE(index.find("data-point=\"vulkan/full-shader\""), std::string::npos);
  EXPECT_NE(index.find("data-point=\"gl-egl/per-object\""), std::string::npos);
  EXPECT_EQ(frontPoints(readFile(dir_ / "vulkan.html")),
            (std::set<std::string>{"vulkan/legacy-4+4", "vulkan/per-object", "vulkan/all-lights"}));
  EXPECT_EQ(frontPoints(readFile(dir_ / "gl-egl.html")),
            (std::set<std::string>{"gl-egl/legacy-4+4", "gl-egl/per-object", "gl-egl/all-lights"}));
  // The table under the plot: vulkan all-lights is 10 ms / 0.5 ms = 20 times its limit; CPU 5 ms (the
  // median aggregate's cpu_time); CV = stddev / mean = 0.27 / 10.08 = 2.68 %.
  EXPECT_NE(index.find("<tr class=\"front\"><td>vulkan</td><td>all-lights</td><td>yes</td><td class=\"n\">10</td>"
                       "<td class=\"n\">5</td><td class=\"n\">9.8</td><td class=\"n\">10.5</td>"
                       "<td class=\"n\">2.68</td><td class=\"n\">5</td><td class=\"n\">0.0001"
                       "</td><td class=\"n\">0.002</td><td class=\"n\">60.5</td><td class=\"n\">20</td>"
                       // x two-term: 10 ms over a P + b P L = 0.5 + 0.1 * 12.5 = 1.75 ms (bench_sample.cpp).
                       "<td class=\"n\">5.71</td></tr>"),
            std::string::npos);
  // The fit itself: 5 points, a = 0.5 ms / 921600 = 0.5425 ns a pixel, b = 0.1 ms / 921600 = 0.1085 ns a
  // pixel-light; gl-egl's curve has no pixel counters, so no fit and no row.
  EXPECT_NE(index.find("<tr><td>vulkan</td><td>5</td><td>0.543</td><td>0.109</td>"), std::string::npos);
  const std::size_t twoTerm = index.find("id=\"two-term\"");
  ASSERT_NE(twoTerm, std::string::npos);
  const std::string twoTermTable = index.substr(twoTerm, index.find("</table>", twoTerm) - twoTerm);
  EXPECT_EQ(count(twoTermTable, "<tr><td>"), 1) << twoTermTable;
}

TEST_F(BenchPages, MetadataTablesAndFits) {
  const std::string index = readFile(dir_ / "index.html");
  for (const char* text : {"v0.2-7-gdeadbee", "2026-12-01T16:00:00Z", "420.500 s", "lightcts bench --out out/bench",
                           "38.4 GFLOP/s on 2 cores", "Mesa 22.3.6", "1.3.230", "NotSupported",
                           "href=\"vulkan.html\"", "2e-05 ms \u00b7 N, RMS 3.1 %", "1.5e-07 ms \u00b7 NlgN, RMS 12 %",
                           "prepare/cpu/lights64-1280x720/all-lights"})
    EXPECT_NE(index.find(text), std::string::npos) << text;
  const std::string vulkan = readFile(dir_ / "vulkan.html");
  for (const char* text : {"<th>device ms</th>", "<th>wall ms</th>", "<th>\u00d7 limit</th>", "<th>pixels/s</th>",
                           "<th>err_rmse</th>", "<th>err_max_abs</th>", "frame_readback (1)", "pipeline (1)",
                           "frame/vulkan/curve-resolution/all-lights/1280x720", "context.library_build_type"})
    EXPECT_NE(vulkan.find(text), std::string::npos) << text;
  const std::string gl = readFile(dir_ / "gl-egl.html");
  EXPECT_EQ(gl.find("<th>device ms</th>"), std::string::npos) << "no device times on gl-egl: no column";
}

TEST_F(BenchPages, EscapesText) {
  const std::string index = readFile(dir_ / "index.html");
  EXPECT_NE(index.find("libOSMesa.so.8 &lt;not found&gt; &amp; &quot;quoted&quot;"), std::string::npos);
  EXPECT_NE(index.find("llvmpipe (LLVM 15.0.6, 256 bits) &lt;b&gt;"), std::string::npos);
  EXPECT_NE(index.find("Test CPU &lt;8 cores&gt;"), std::string::npos);
  EXPECT_EQ(index.find("<b>"), std::string::npos);
  EXPECT_EQ(index.find("<not found>"), std::string::npos);
  const std::string vulkan = readFile(dir_ / "vulkan.html");
  EXPECT_NE(vulkan.find("error: compile &lt;failed&gt; &amp; &quot;x&quot;"), std::string::npos);
  EXPECT_NE(vulkan.find("legacy-4+4"), std::string::npos);
}

TEST(BenchReport, RejectsOtherFormats) {
  EXPECT_THROW(writeBenchReport(nlohmann::ordered_json::parse(R"({"format": "lightcts-results"})"),
                                fs::temp_directory_path() / "lightcts-never-written"),
               std::invalid_argument);
  EXPECT_THROW(writeBenchReport(nlohmann::ordered_json::array(), fs::temp_directory_path() / "lightcts-never-written"),
               std::invalid_argument);
  EXPECT_FALSE(fs::exists(fs::temp_directory_path() / "lightcts-never-written"));
}

// The benchmark pages and the conformance report are written in the one page
// frame (html_page.h): the same head and base stylesheet, each page adding only
// its own rules, and the same end.
TEST(BenchReport, SharesThePageFrameWithTheConformanceReport) {
  std::ostringstream frame;
  html::pageStart(frame, "title", "");
  const std::string head = frame.str();
  const std::string base = head.substr(head.find("<style>"), head.find("</style>") - head.find("<style>"));
  const std::string bench = benchOverviewHtml(testing::sampleBench());
  const std::string report = htmlReport(results::RunRecord{}, "run", "run/report");
  for (const std::string* page : {&bench, &report}) {
    EXPECT_EQ(page->rfind("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>", 0), 0u);
    EXPECT_EQ(page->find(base), page->find("<style>")) << "the base stylesheet opens the <style>";
    EXPECT_EQ(count(*page, "<style>"), 1);
    EXPECT_TRUE(page->ends_with("</body>\n</html>\n"));
  }
  EXPECT_NE(bench.find("svg.plot {"), std::string::npos);
  EXPECT_EQ(report.find("svg.plot {"), std::string::npos) << "a page's own rules stay on that page";
  EXPECT_NE(report.find(".v-Pass"), std::string::npos);
  EXPECT_EQ(bench.find(".v-Pass"), std::string::npos);
}

// A broken mode (NaN or infinite pixels) is never a point. The
// field on vulkan, median ms and err_rmse: all-lights 10 1e-4, deferred-hdr32
// 5 2e-4, deferred-ldr8 3 with 1200 non-finite pixels (its error counters
// null, as bench.json writes them), deferred-hdr16 2 with 7 non-finite pixels
// and a zero error (what a writer without null would write). Were
// hdr16 a point, (2 ms, 0) would dominate every other: the front would be it
// alone. Without the broken two the front is hdr32 and all-lights. The
// lightmap scene has one mode, realtime, broken: its scene has no plot.
nlohmann::ordered_json brokenBench() {
  using Json = nlohmann::ordered_json;
  const auto run = [](const std::string& name, double ms, const Json& counters) {
    Json r = {{"name", name}, {"run_name", name}, {"run_type", "iteration"}, {"iterations", 10},
              {"real_time", ms}, {"cpu_time", ms}, {"time_unit", "ms"}};
    for (auto it = counters.begin(); it != counters.end(); ++it) r[it.key()] = it.value();
    return r;
  };
  const auto fine = [](double rmse) {
    return Json{{"err_rmse", rmse}, {"err_max_abs", 10 * rmse}, {"err_psnr_db", 50.0}, {"err_perceptual_fail", 0.0},
                {"err_nonfinite_pixels", 0}};
  };
  const Json broken = {{"err_rmse", nullptr}, {"err_max_abs", nullptr}, {"err_psnr_db", nullptr},
                       {"err_perceptual_fail", 0.25}, {"err_nonfinite_pixels", 1200}};
  const Json zeroed = {{"err_rmse", 0.0}, {"err_max_abs", 0.0}, {"err_psnr_db", 0.0}, {"err_perceptual_fail", 0.0},
                       {"err_nonfinite_pixels", 7}};
  const std::string field = "frame/vulkan/lights64-1280x720/";
  const Json benchmarks = {run(field + "all-lights", 10, fine(1e-4)), run(field + "deferred-hdr32", 5, fine(2e-4)),
                           run(field + "deferred-ldr8", 3, broken), run(field + "deferred-hdr16", 2, zeroed),
                           run("frame/vulkan/lightmap-1280x720/realtime", 4, broken)};
  return {{"format", "lightcts-bench"},
          {"backends", Json::array({{{"backend", "vulkan"}, {"status", "ran"}, {"benchmarks", benchmarks}}})}};
}

TEST(BenchReport, ABrokenModeIsListedAsBrokenAndNeverAPoint) {
  const BenchSet set = readBenchFile(brokenBench());
  EXPECT_FALSE(entry(set, "frame/vulkan/lights64-1280x720/deferred-ldr8").counters.count("err_rmse"))
      << "null reads as absent";
  for (const std::string& page : {benchOverviewHtml(brokenBench()), benchBackendHtml(brokenBench(), "vulkan")}) {
    EXPECT_EQ(frontPoints(page), (std::set<std::string>{"vulkan/deferred-hdr32", "vulkan/all-lights"}));
    EXPECT_EQ(count(page, "<svg "), 1) << "the field's scatter; the lightmap scene's only mode is broken";
    EXPECT_EQ(count(page, "<circle class=\"pt"), 2);
    EXPECT_EQ(page.find("data-point=\"vulkan/deferred-ldr8\""), std::string::npos);
    EXPECT_EQ(page.find("data-point=\"vulkan/deferred-hdr16\""), std::string::npos);
    // The Pareto table: the points in time order, then the broken modes in time order.
    const std::size_t hdr32 = page.find("<td>deferred-hdr32</td><td>yes</td>");
    const std::size_t hdr16 = page.find(
        "<tr class=\"broken\"><td>vulkan</td><td>deferred-hdr16 <span class=\"err\">broken: 7 non-finite "
        "pixels</span></td><td>no: broken</td><td class=\"n\">2</td>");
    const std::size_t ldr8 = page.find(
        "<tr class=\"broken\"><td>vulkan</td><td>deferred-ldr8 <span class=\"err\">broken: 1200 non-finite "
        "pixels</span></td><td>no: broken</td><td class=\"n\">3</td><td class=\"n\">3</td><td class=\"n\">3</td>"
        "<td class=\"n\">3</td><td class=\"n\">-</td><td class=\"n\">1</td><td class=\"n\">-</td>"
        "<td class=\"n\">-</td><td class=\"n\">-</td>");
    ASSERT_NE(hdr32, std::string::npos);
    ASSERT_NE(hdr16, std::string::npos);
    ASSERT_NE(ldr8, std::string::npos);
    EXPECT_LT(page.find("<td>all-lights</td><td>yes</td>"), hdr16);
    EXPECT_LT(hdr16, ldr8);
    // The lightmap scene: its heading and its table, no plot.
    EXPECT_NE(page.find("<h3>lightmap-1280x720</h3>\n<table class=\"bench pareto\">"), std::string::npos);
    EXPECT_NE(page.find("<td>realtime <span class=\"err\">broken: 1200 non-finite pixels</span></td>"),
              std::string::npos);
  }
  // Every benchmark on the backend's page: marked, with the count in its column.
  const std::string vulkan = benchBackendHtml(brokenBench(), "vulkan");
  EXPECT_NE(vulkan.find("<tr class=\"broken\"><td>frame/vulkan/lights64-1280x720/deferred-ldr8 <span "
                        "class=\"err\">broken: 1200 non-finite pixels</span></td>"),
            std::string::npos);
  EXPECT_NE(vulkan.find("<th>err_nonfinite_pixels</th>"), std::string::npos);
  EXPECT_NE(vulkan.find("<tr><td>frame/vulkan/lights64-1280x720/all-lights</td>"), std::string::npos);
}

// SPEC 3.9's shadow-map modes get their own section per backend: the
// front of resolution and filter among them alone, with the shadow passes'
// time. Hand-derived: hard-256 (5 ms, 0.02) and bilinear-1024 (7 ms, 0.01)
// are on the front; bilinear-256 (6 ms, 0.03) is slower and worse than
// hard-256, so it is not.
nlohmann::ordered_json spreadBench();  // below

TEST(BenchReport, ShadowMapModesHaveTheirOwnFrontPerBackend) {
  using Json = nlohmann::ordered_json;
  const auto run = [](const std::string& mode, double ms, double error, double shadowMs) {
    const std::string name = "frame/vulkan/lights64-1280x720/" + mode;
    return Json{{"name", name}, {"run_name", name}, {"run_type", "iteration"}, {"iterations", 3},
                {"real_time", ms}, {"cpu_time", ms}, {"time_unit", "ms"}, {"err_rmse", error},
                {"err_max_abs", error}, {"err_psnr_db", 40.0}, {"err_nonfinite_pixels", 0}, {"shadow_pass_ms", shadowMs}};
  };
  const Json bench = {{"format", "lightcts-bench"},
                      {"backends", Json::array({{{"backend", "vulkan"}, {"status", "ran"},
                                                 {"benchmarks", Json::array({run("shadows-hard-256", 5, 0.02, 1),
                                                                             run("shadows-bilinear-256", 6, 0.03, 1),
                                                                             run("shadows-bilinear-1024", 7, 0.01, 3),
                                                                             run("all-lights", 4, 0.001, 0)})}}})}};
  const std::string page = benchOverviewHtml(bench);
  const std::size_t section = page.find("<h2 id=\"shadow-maps\">Shadow maps: resolution and filter</h2>");
  ASSERT_NE(section, std::string::npos);
  const std::string shadows = page.substr(section);
  EXPECT_EQ(frontPoints(shadows), (std::set<std::string>{"vulkan/shadows-hard-256", "vulkan/shadows-bilinear-1024"}));
  EXPECT_EQ(shadows.find("data-point=\"vulkan/all-lights\""), std::string::npos) << "shadow modes only";
  EXPECT_NE(shadows.find("<th>shadow pass ms</th>"), std::string::npos);
  // No shadow modes, no section.
  EXPECT_EQ(benchOverviewHtml(spreadBench()).find("id=\"shadow-maps\""), std::string::npos);
}

// A tiny bench.json: a, three repetitions (real 8, 10, 12 ms; CPU 3, 4, 7);
// b, one repetition; c, Google Benchmark's median and cv aggregates only.
nlohmann::ordered_json spreadBench() {
  using Json = nlohmann::ordered_json;
  const auto run = [](const std::string& name, double real, double cpu) {
    return Json{{"name", name}, {"run_name", name}, {"run_type", "iteration"}, {"iterations", 10},
                {"real_time", real}, {"cpu_time", cpu}, {"time_unit", "ms"}};
  };
  const auto aggregate = [](const std::string& which, double real, double cpu, const char* unit) {
    return Json{{"name", "pipeline/vulkan/s/c_" + which}, {"run_name", "pipeline/vulkan/s/c"},
                {"run_type", "aggregate"}, {"aggregate_name", which}, {"aggregate_unit", unit},
                {"repetitions", 4}, {"real_time", real}, {"cpu_time", cpu}, {"time_unit", "us"}};
  };
  const Json benchmarks = {run("pipeline/vulkan/s/a", 8, 3), run("pipeline/vulkan/s/a", 12, 7),
                           run("pipeline/vulkan/s/a", 10, 4), run("pipeline/vulkan/s/b", 5, 2),
                           aggregate("median", 4000, 1000, "time"), aggregate("cv", 0.125, 0.5, "percentage")};
  return {{"format", "lightcts-bench"},
          {"backends", Json::array({{{"backend", "vulkan"}, {"status", "ran"}, {"benchmarks", benchmarks}}})}};
}

TEST(BenchReport, TablesHaveCpuTimeAndCoefficientOfVariation) {
  const std::string page = benchBackendHtml(spreadBench(), "vulkan");
  EXPECT_NE(page.find("<tr><th>benchmark</th><th>median ms</th><th>CPU ms</th><th>min ms</th><th>max ms</th>"
                      "<th>stddev ms</th><th>CV %</th><th>n</th></tr>"),
            std::string::npos);
  // a: median 10, CPU median 4; mean 10, sample stddev sqrt((4 + 0 + 4) / 2) = 2, CV 2 / 10 = 20 %.
  EXPECT_NE(page.find("<tr><td>pipeline/vulkan/s/a</td><td class=\"n\">10</td><td class=\"n\">4</td>"
                      "<td class=\"n\">8</td><td class=\"n\">12</td><td class=\"n\">2</td>"
                      "<td class=\"n\">20</td><td class=\"n\">3</td></tr>"),
            std::string::npos);
  // b: one repetition, no stddev nor CV.
  EXPECT_NE(page.find("<tr><td>pipeline/vulkan/s/b</td><td class=\"n\">5</td><td class=\"n\">2</td>"
                      "<td class=\"n\">5</td><td class=\"n\">5</td><td class=\"n\">-</td>"
                      "<td class=\"n\">-</td><td class=\"n\">1</td></tr>"),
            std::string::npos);
  // c: 4000 us = 4 ms, CPU 1 ms; the cv aggregate 0.125 (a fraction, not microseconds) is 12.5 %.
  EXPECT_NE(page.find("<tr><td>pipeline/vulkan/s/c</td><td class=\"n\">4</td><td class=\"n\">1</td>"
                      "<td class=\"n\">-</td><td class=\"n\">-</td><td class=\"n\">-</td>"
                      "<td class=\"n\">12.5</td><td class=\"n\">4</td></tr>"),
            std::string::npos);
}

TEST(BenchReport, EmptyBenchStillWritesPages) {
  const std::string html = benchOverviewHtml(nlohmann::ordered_json::parse(R"({"format": "lightcts-bench"})"));
  EXPECT_NE(html.find("No frame benchmark has error counters."), std::string::npos);
  EXPECT_EQ(count(html, "<svg "), 0);
}

}  // namespace
}  // namespace reports
