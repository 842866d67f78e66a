// Where a plot's point labels go (svg_plot.cpp draws them): no label over
// another label or over any point, every label inside the plot's frame.
// Points that lie on one spot (within a few pixels) share one label that
// names the group; the groups with a point on the Pareto front are placed
// first, then as many others as fit; a label set away from its point gets a
// leader line. Text is measured as the monospace font the labels are drawn
// in, so the boxes here are the boxes a browser draws (the Chromium check
// of reports/tests/check_svgs_render.sh measures them with getBBox).
#pragma once

#include <string>
#include <vector>

namespace reports::svg {

struct LabelBox {
  double x0, y0, x1, y1;
};

// One labelled point, in pixels.
struct LabelRequest {
  double px, py;
  std::string text;
  std::string title;   // the point's hover text
  bool front = false;  // on the Pareto front: placed first, drawn bold
};

struct PlacedLabel {
  std::string text;   // the point's label, or the group's
  std::string title;  // every member's hover text, one a line
  bool bold = false;
  bool leader = false;  // draw a line from (px, py) to the box
  double px, py;        // the point (the group's first) the label belongs to
  LabelBox box;         // the text starts at box.x0, its baseline at box.y0 + kLabelBaseline
};

inline constexpr double kLabelFontSize = 10;
// Monospace at 10 px: every glyph 0.6 em wide (DejaVu Sans Mono and
// Liberation Mono, Debian's monospace fonts); a little more, so a
// slightly wider font still fits its box.
inline constexpr double kLabelCharWidth = 6.2;
inline constexpr double kLabelHeight = 12;
// The baseline below a box's top: the font's ascent (0.93 em) and descent
// (0.24 em) both inside the box.
inline constexpr double kLabelBaseline = 9.5;

// Places the labels of `requests` inside `frame`, clear of `markers` (each
// point's box) and of each other; a request that finds no place is left out.
std::vector<PlacedLabel> placeLabels(const std::vector<LabelRequest>& requests, const std::vector<LabelBox>& markers,
                                     const LabelBox& frame);

// The label of points sharing one spot: their labels joined when short,
// else their common prefix and the count ("shadows-* (9)"), else the first
// and how many more.
std::string groupLabel(const std::vector<std::string>& labels);

}  // namespace reports::svg
