// The series builder and the points of reports/svg_plot.h, which every plot
// of the benchmark pages is made with.
#include "reports/svg_plot.h"

#include <gtest/gtest.h>

#include <array>
#include <regex>
#include <string>
#include <vector>

namespace reports::svg {
namespace {

long long count(const std::string& text, const std::string& what) {
  long long n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(SvgSeriesBuilder, OneSeriesPerGroupInFirstAppearanceOrderStyledByItsFirstPoint) {
  Plot plot;
  SeriesBuilder series(plot);
  series.add("vulkan", {2, false, false}, pointAt(4, 40));
  series.add("gl-egl", {0, true, true}, pointAt(1, 10));
  series.add("vulkan", {5, true, true}, pointAt(2, 20));  // the series keeps the style it started with
  ASSERT_EQ(plot.series.size(), 2u);
  EXPECT_EQ(plot.series[0].name, "vulkan");
  EXPECT_EQ(plot.series[0].colour, colour(2));
  EXPECT_FALSE(plot.series[0].line);
  EXPECT_FALSE(plot.series[0].dashed);
  ASSERT_EQ(plot.series[0].points.size(), 2u);
  EXPECT_EQ(plot.series[0].points[0].x, 4);
  EXPECT_EQ(plot.series[1].name, "gl-egl");
  EXPECT_EQ(plot.series[1].colour, colour(0));
  EXPECT_TRUE(plot.series[1].dashed);
}

TEST(SvgSeriesBuilder, SortPointsByXIsStable) {
  Plot plot;
  SeriesBuilder series(plot);
  for (const auto& [x, y] : {std::pair{3.0, 1.0}, {1.0, 2.0}, {3.0, 3.0}, {2.0, 4.0}})
    series.add("a", {}, pointAt(x, y));
  sortPointsByX(plot);
  std::vector<std::pair<double, double>> order;
  for (const Point& p : plot.series[0].points) order.emplace_back(p.x, p.y);
  EXPECT_EQ(order, (std::vector<std::pair<double, double>>{{1, 2}, {2, 4}, {3, 1}, {3, 3}}));
}

TEST(SvgPoint, PointAtSetsOnlyTheCoordinates) {
  const Point p = pointAt(1.5, -2);
  EXPECT_EQ(p.x, 1.5);
  EXPECT_EQ(p.y, -2);
  EXPECT_FALSE(p.yLow || p.yHigh || p.highlight);
  EXPECT_TRUE(p.label.empty() && p.id.empty());
}


TEST(SvgTicks, LogAxisTicksEveryDecadeAndHalfDecade) {
  // 0.3 to 40: the half-decades 10^(k/2) inside it are k = -1 .. 3 (10^-1 = 0.1 and 10^2 = 100 are outside).
  const std::vector<double> t = ticks(Scale::Log10, 0.3, 40);
  const std::vector<double> expected = {0.316227766, 1, 3.16227766, 10, 31.6227766};
  ASSERT_EQ(t.size(), expected.size());
  for (std::size_t i = 0; i < t.size(); ++i) EXPECT_NEAR(t[i], expected[i], 1e-8) << i;
  std::vector<std::string> labels;
  for (double v : t) labels.push_back(tickText(v));
  EXPECT_EQ(labels, (std::vector<std::string>{"0.316", "1", "3.16", "10", "31.6"}));
  EXPECT_EQ(tickText(3162.2776), "3.16k");
  // 1.5 to 8 holds one half-decade (3.16): 2 and 5 join it.
  const std::vector<double> narrow = ticks(Scale::Log10, 1.5, 8);
  ASSERT_EQ(narrow.size(), 3u);
  EXPECT_NEAR(narrow[0], 2, 1e-12);
  EXPECT_NEAR(narrow[1], 3.16227766, 1e-8);
  EXPECT_NEAR(narrow[2], 5, 1e-12);
}

TEST(SvgRender, LogAxisTicksAreLabelled) {
  Plot plot;
  plot.x = {"ms", Scale::Log10, false};
  SeriesBuilder series(plot);
  series.add("a", {0, false, false}, pointAt(0.3, 1));
  series.add("a", {0, false, false}, pointAt(40, 2));
  const std::string svg = render(plot);
  for (const char* label : {">0.316</text>", ">1</text>", ">3.16</text>", ">10</text>", ">31.6</text>"})
    EXPECT_NE(svg.find(label), std::string::npos) << label;
}

// The <line> elements of class "whisker" in `svg`, as (x1, y1, x2, y2).
std::vector<std::array<double, 4>> whiskers(const std::string& svg) {
  std::vector<std::array<double, 4>> out;
  const std::regex line(
      "<line class=\"whisker\" x1=\"([-0-9.]+)\" y1=\"([-0-9.]+)\" x2=\"([-0-9.]+)\" y2=\"([-0-9.]+)\"");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), line); it != std::sregex_iterator(); ++it)
    out.push_back({std::stod((*it)[1]), std::stod((*it)[2]), std::stod((*it)[3]), std::stod((*it)[4])});
  return out;
}

TEST(SvgRender, ScatterPointWithMinMaxHasAHorizontalWhisker) {
  Plot plot;
  plot.x = {"ms", Scale::Linear, true};
  plot.y = {"err", Scale::Linear, true};
  SeriesBuilder series(plot);
  Point p = pointAt(10, 1);
  p.xLow = 8;
  p.xHigh = 12;
  series.add("a", {0, false, false}, p);
  series.add("a", {0, false, false}, pointAt(5, 2));  // no min/max: no whisker
  const std::string svg = render(plot);
  const auto found = whiskers(svg);
  ASSERT_EQ(found.size(), 1u) << svg;
  // x: 0 .. 12 * 1.05 = 12.6 across 78 .. 580 (760 - 180); y: 0 .. 2.1 across 348 .. 34.
  EXPECT_NEAR(found[0][0], 78 + 8 / 12.6 * 502, 0.06);
  EXPECT_NEAR(found[0][2], 78 + 12 / 12.6 * 502, 0.06);
  EXPECT_NEAR(found[0][1], 348 - 1 / 2.1 * 314, 0.06);
  EXPECT_EQ(found[0][1], found[0][3]);
}

std::string legendOf(const std::string& svg) {
  const std::size_t at = svg.find("<g class=\"legend\"");
  return at == std::string::npos ? "" : svg.substr(at, svg.find("</g>", at) - at);
}

TEST(SvgRender, LegendOfAScatterOnlySeriesIsAMarkerWithoutALine) {
  Plot plot;
  SeriesBuilder series(plot);
  series.add("points", {0, false, false}, pointAt(1, 1));
  series.add("points", {0, false, false}, pointAt(2, 3));
  const std::string scatterOnly = legendOf(render(plot));
  EXPECT_NE(scatterOnly.find(">points</text>"), std::string::npos);
  EXPECT_EQ(scatterOnly.find("<line"), std::string::npos) << scatterOnly;
  EXPECT_NE(scatterOnly.find("<circle"), std::string::npos);
  // A series with a line keeps its line in the legend.
  series.add("curve", {1, true, false}, pointAt(1, 2));
  series.add("curve", {1, true, false}, pointAt(2, 2));
  const std::string both = legendOf(render(plot));
  EXPECT_EQ(count(both, "<line"), 1);
  EXPECT_EQ(count(both, "<circle"), 2);
}

}  // namespace
}  // namespace reports::svg
