// The series builder and the points of reports/svg_plot.h, which every plot
// of the benchmark pages is made with.
#include "reports/svg_plot.h"

#include <gtest/gtest.h>

namespace reports::svg {
namespace {

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

}  // namespace
}  // namespace reports::svg
