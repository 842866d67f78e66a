// A small inline-SVG plot writer for the benchmark pages: scatter and line
// plots on linear, log10 or log2 axes, with ticks, axis labels, point labels,
// min-max whiskers and a legend. No script, no external resources: the
// result is one <svg> element to put inside an HTML page.
#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace reports::svg {

enum class Scale { Linear, Log10, Log2 };

struct Axis {
  std::string label;
  Scale scale = Scale::Linear;
  bool fromZero = true;  // linear axes start at 0 (when the data is non-negative)
};

struct Point {
  double x = 0, y = 0;
  std::optional<double> yLow, yHigh;  // a vertical whisker (min and max over repetitions)
  std::optional<double> xLow, xHigh;  // a horizontal whisker (the scatter's time axis)
  std::string label;                  // drawn beside the point where it fits ("" for none): svg_labels.h
  std::string id;                     // data-point attribute, and the tooltip when `title` is empty
  std::string title;                  // the tooltip (hover text)
  bool highlight = false;             // drawn with a ring, class "front"; its label is placed first
};

struct Series {
  std::string name;  // legend entry ("" for none)
  std::string colour;
  std::vector<Point> points;
  bool line = true;      // connect the points in order; false: its legend entry is a marker only
  bool markers = true;
  bool dashed = false;
  bool steps = false;    // connect with horizontal-then-vertical steps
  std::string cssClass;  // class of the series' <g>
};

struct Plot {
  std::string title;
  Axis x, y;
  std::vector<Series> series;
  int width = 760, height = 400;
};

// The <svg> element; points with non-finite coordinates, or non-positive
// ones on a log axis, are left out. Text is escaped.
std::string render(const Plot& plot);

// A point at (x, y), nothing else set.
Point pointAt(double x, double y);

// How SeriesBuilder starts a series.
struct SeriesStyle {
  std::size_t colourIndex = 0;  // colour(colourIndex)
  bool line = true;
  bool dashed = false;
};

// Turns points that each belong to a named group (a backend, a mode, a
// quantity) into one series per group, in order of first appearance: how
// every plot of the benchmark pages gets its series.
class SeriesBuilder {
 public:
  explicit SeriesBuilder(Plot& plot) : plot_(plot) {}
  // Adds `point` to the series `name`; the group's first point starts the
  // series with `style`.
  void add(const std::string& name, const SeriesStyle& style, Point point);

 private:
  Plot& plot_;
  std::map<std::string, std::size_t> index_;
};

// The points of every series in ascending x (stable: equal x keep their
// order), so that lines run left to right.
void sortPointsByX(Plot& plot);

// Distinct colours, by index (cycling).
const std::string& colour(std::size_t index);

// Tick positions (in data units) for an axis over [low, high], ascending.
// Log10: every decade and half-decade, 10^(k/2) (0.316, 1, 3.16, 10, ...);
// when fewer than three of those fall in the range, 2 and 5 times each
// decade as well. Log2: the powers of two (at most about ten). Linear, and
// any log axis still left with fewer than two: 1-2-5 steps.
std::vector<double> ticks(Scale scale, double low, double high);
// "0.5", "12", "1.5k", "100k", "2M".
std::string tickText(double value);

}  // namespace reports::svg
