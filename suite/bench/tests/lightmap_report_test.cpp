// The lightmap modes on the benchmark pages (reports/bench_report.h,
// docs/bench-report.md): a hand-written bench.json with lightmap-16,
// lightmap-64 and realtime on one backend, and one without any lightmap mode.
#include "reports/bench_report.h"

#include <gtest/gtest.h>

#include <string>

namespace {

using Json = nlohmann::ordered_json;

Json frameRun(const std::string& mode, double ms, double rmse, double maxAbs, double bakeMs) {
  Json run = {{"name", "frame/vulkan/lightmap-1280x720/" + mode},
              {"run_name", "frame/vulkan/lightmap-1280x720/" + mode},
              {"run_type", "iteration"},
              {"iterations", 10},
              {"real_time", ms},
              {"cpu_time", ms},
              {"time_unit", "ms"},
              {"err_rmse", rmse},
              {"err_max_abs", maxAbs},
              {"err_psnr_db", 40.0},
              {"err_perceptual_fail", 0.0}};
  if (bakeMs > 0) run["bake_ms"] = bakeMs, run["bake_runs"] = 5, run["lightmap_texels"] = 256;
  return run;
}

Json benchWith(const Json& benchmarks) {
  return {{"format", "lightcts-bench"},
          {"version", 1},
          {"backends", Json::array({{{"backend", "vulkan"}, {"status", "ran"}, {"benchmarks", benchmarks}}})}};
}

std::string section(const std::string& page) {
  const std::size_t start = page.find("<h2 id=\"lightmap\">");
  if (start == std::string::npos) return "";
  return page.substr(start, page.find("<h2", start + 1) - start);
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(LightmapReport, SectionPlotsAndTablesEveryResolutionWithTheRealtimeRow) {
  const Json bench = benchWith(Json::array({frameRun("lightmap-16", 11, 0.11, 3.2, 0.25),
                                            frameRun("lightmap-64", 12, 0.0099, 0.53, 12.5),
                                            frameRun("realtime", 30, 4e-7, 1e-5, 0)}));
  for (const std::string& page : {reports::benchOverviewHtml(bench), reports::benchBackendHtml(bench, "vulkan")}) {
    const std::string s = section(page);
    ASSERT_FALSE(s.empty());
    EXPECT_EQ(count(s, "<svg"), 2u);  // error and time against N
    // N, bake ms, bake runs, frame ms, CPU ms (cpu_time is 11 too), CV ("-":
    // one repetition has no spread), then the errors.
    EXPECT_NE(s.find("<td>lightmap-16</td><td class=\"n\">16</td><td class=\"n\">0.25</td><td class=\"n\">5</td>"
                     "<td class=\"n\">11</td><td class=\"n\">11</td><td class=\"n\">-</td>"
                     "<td class=\"n\">0.11</td><td class=\"n\">3.2</td>"),
              std::string::npos);
    EXPECT_NE(s.find("<td>lightmap-64</td><td class=\"n\">64</td><td class=\"n\">12.5</td>"), std::string::npos);
    EXPECT_NE(s.find("<td>realtime</td><td class=\"n\">-</td><td class=\"n\">-</td>"), std::string::npos);
    EXPECT_LT(s.find("lightmap-64</td>"), s.find("realtime</td>"));  // the real-time row comes last
    // The scatter of the scene shows all three, with the bake time beside.
    EXPECT_NE(page.find("lightmap-1280x720: speed against error"), std::string::npos);
    EXPECT_NE(page.find("<th>bake ms</th><th>\u00d7 limit</th>"), std::string::npos);
  }
}

TEST(LightmapReport, NoSectionWithoutLightmapModes) {
  const Json bench = benchWith(Json::array({frameRun("realtime", 30, 4e-7, 1e-5, 0)}));
  EXPECT_TRUE(section(reports::benchOverviewHtml(bench)).empty());
  EXPECT_EQ(reports::benchOverviewHtml(bench).find("<th>bake ms</th>"), std::string::npos);
}

}  // namespace
