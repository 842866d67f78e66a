#include "reports/svg_plot.h"

#include "reports/html_escape.h"
#include "reports/svg_labels.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <utility>

namespace reports::svg {
namespace {

constexpr double kLeft = 78, kRight = 180, kTop = 34, kBottom = 52;

std::string num(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f", v);
  return text;
}

bool usable(Scale scale, double v) { return std::isfinite(v) && (scale == Scale::Linear || v > 0); }

struct Range {
  Scale scale;
  double low = 0, high = 1;
  double t(double v) const {  // 0..1 across the axis
    if (scale == Scale::Linear) return (v - low) / (high - low);
    return (std::log(v) - std::log(low)) / (std::log(high) - std::log(low));
  }
};

Range rangeOf(const Axis& axis, std::vector<double> values) {
  Range r{axis.scale};
  values.erase(std::remove_if(values.begin(), values.end(), [&](double v) { return !usable(axis.scale, v); }),
               values.end());
  if (values.empty()) {
    r.low = axis.scale == Scale::Linear ? 0 : 1;
    r.high = axis.scale == Scale::Linear ? 1 : 10;
    return r;
  }
  double lo = *std::min_element(values.begin(), values.end());
  double hi = *std::max_element(values.begin(), values.end());
  if (axis.scale == Scale::Linear) {
    if (axis.fromZero && lo >= 0) lo = 0;
    if (hi == lo) {
      const double pad = lo == 0 ? 1 : std::abs(lo) * 0.1;
      lo -= axis.fromZero && lo == 0 ? 0 : pad;
      hi += pad;
    }
    const double pad = (hi - lo) * 0.05;
    r.low = (axis.fromZero && lo == 0) ? 0 : lo - pad;
    r.high = hi + pad;
  } else {
    if (hi == lo) lo /= 2, hi *= 2;
    const double pad = std::pow(hi / lo, 0.05);
    r.low = lo / pad;
    r.high = hi * pad;
  }
  return r;
}

std::vector<double> linearTicks(double low, double high) {
  std::vector<double> out;
  const double raw = (high - low) / 6;
  if (!(raw > 0)) return out;
  const double magnitude = std::pow(10, std::floor(std::log10(raw)));
  double step = magnitude;
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * magnitude >= raw) {
      step = m * magnitude;
      break;
    }
  for (double v = std::ceil(low / step) * step; v <= high + step * 1e-9; v += step)
    out.push_back(std::abs(v) < step * 1e-9 ? 0 : v);
  return out;
}

}  // namespace

const std::string& colour(std::size_t index) {
  static const std::vector<std::string> colours = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd",
                                                   "#8c564b", "#e377c2", "#17becf", "#7f7f7f", "#bcbd22"};
  return colours[index % colours.size()];
}

std::vector<double> ticks(Scale scale, double low, double high) {
  std::vector<double> out;
  if (scale == Scale::Log10) {
    const auto inRange = [&](double v) { return v >= low * (1 - 1e-12) && v <= high * (1 + 1e-12); };
    // Decades and half-decades: 10^(k/2), k from the half-decade at or below low.
    for (int k = int(std::floor(2 * std::log10(low))); k <= int(std::ceil(2 * std::log10(high))); ++k) {
      const double v = std::pow(10.0, k / 2.0);
      if (inRange(v)) out.push_back(v);
    }
    if (out.size() < 3) {  // a narrow range: 2 and 5 times each decade too
      for (int e = int(std::floor(std::log10(low))); e <= int(std::ceil(std::log10(high))); ++e)
        for (double m : {2.0, 5.0})
          if (const double v = m * std::pow(10.0, e); inRange(v)) out.push_back(v);
      std::sort(out.begin(), out.end());
    }
  } else if (scale == Scale::Log2) {
    std::vector<double> all;
    for (int e = int(std::floor(std::log2(low))); e <= int(std::ceil(std::log2(high))); ++e) {
      const double v = std::ldexp(1.0, e);
      if (v >= low * (1 - 1e-12) && v <= high * (1 + 1e-12)) all.push_back(v);
    }
    const std::size_t every = all.size() > 10 ? (all.size() + 9) / 10 : 1;
    for (std::size_t i = 0; i < all.size(); i += every) out.push_back(all[i]);
  }
  if (out.size() < 2) out = linearTicks(low, high);
  return out;
}

std::string tickText(double value) {
  char text[32];
  const double a = std::abs(value);
  if (a >= 1e6 && a < 1e15) std::snprintf(text, sizeof text, "%.3gM", value / 1e6);
  else if (a >= 1e3 && a < 1e6) std::snprintf(text, sizeof text, "%.3gk", value / 1e3);
  else std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

std::string render(const Plot& plot) {
  const double W = plot.width, H = plot.height;
  const double x0 = kLeft, x1 = W - kRight, y0 = kTop, y1 = H - kBottom;

  std::vector<double> xs, ys;
  for (const Series& s : plot.series)
    for (const Point& p : s.points) {
      if (!usable(plot.x.scale, p.x) || !usable(plot.y.scale, p.y)) continue;
      xs.push_back(p.x);
      ys.push_back(p.y);
      if (p.xLow) xs.push_back(*p.xLow);
      if (p.xHigh) xs.push_back(*p.xHigh);
      if (p.yLow) ys.push_back(*p.yLow);
      if (p.yHigh) ys.push_back(*p.yHigh);
    }
  const Range rx = rangeOf(plot.x, xs), ry = rangeOf(plot.y, ys);
  const auto X = [&](double v) { return x0 + rx.t(v) * (x1 - x0); };
  const auto Y = [&](double v) { return y1 - ry.t(v) * (y1 - y0); };

  std::ostringstream out;
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"plot\" width=\"" << plot.width << "\" height=\""
      << plot.height << "\" viewBox=\"0 0 " << plot.width << ' ' << plot.height << "\" role=\"img\" aria-label=\""
      << escapeText(plot.title) << "\">\n";
  out << "<title>" << escapeText(plot.title) << "</title>\n";
  out << "<rect x=\"0\" y=\"0\" width=\"" << plot.width << "\" height=\"" << plot.height
      << "\" fill=\"#fff\"/>\n";
  out << "<text x=\"" << num(x0) << "\" y=\"20\" font-size=\"14\" font-weight=\"bold\">" << escapeText(plot.title)
      << "</text>\n";

  // Grid, ticks and tick labels.
  out << "<g class=\"axes\" font-size=\"11\" fill=\"#444\">\n";
  for (double v : ticks(rx.scale, rx.low, rx.high)) {
    if (!usable(rx.scale, v)) continue;
    const std::string px = num(X(v));
    out << "<line x1=\"" << px << "\" y1=\"" << num(y0) << "\" x2=\"" << px << "\" y2=\"" << num(y1)
        << "\" stroke=\"#e4e4e4\"/><line x1=\"" << px << "\" y1=\"" << num(y1) << "\" x2=\"" << px << "\" y2=\""
        << num(y1 + 5) << "\" stroke=\"#444\"/><text x=\"" << px << "\" y=\"" << num(y1 + 18)
        << "\" text-anchor=\"middle\">" << escapeText(tickText(v)) << "</text>\n";
  }
  for (double v : ticks(ry.scale, ry.low, ry.high)) {
    if (!usable(ry.scale, v)) continue;
    const std::string py = num(Y(v));
    out << "<line x1=\"" << num(x0) << "\" y1=\"" << py << "\" x2=\"" << num(x1) << "\" y2=\"" << py
        << "\" stroke=\"#e4e4e4\"/><line x1=\"" << num(x0 - 5) << "\" y1=\"" << py << "\" x2=\"" << num(x0)
        << "\" y2=\"" << py << "\" stroke=\"#444\"/><text x=\"" << num(x0 - 8) << "\" y=\"" << py
        << "\" dy=\"4\" text-anchor=\"end\">" << escapeText(tickText(v)) << "</text>\n";
  }
  out << "<rect x=\"" << num(x0) << "\" y=\"" << num(y0) << "\" width=\"" << num(x1 - x0) << "\" height=\""
      << num(y1 - y0) << "\" fill=\"none\" stroke=\"#444\"/>\n";
  const auto scaleNote = [](Scale s) {
    return s == Scale::Log10 ? " (log)" : s == Scale::Log2 ? " (log2)" : "";
  };
  out << "<text x=\"" << num((x0 + x1) / 2) << "\" y=\"" << num(H - 12) << "\" text-anchor=\"middle\" font-size=\"12\">"
      << escapeText(plot.x.label + scaleNote(plot.x.scale)) << "</text>\n";
  out << "<text transform=\"translate(16 " << num((y0 + y1) / 2)
      << ") rotate(-90)\" text-anchor=\"middle\" font-size=\"12\">"
      << escapeText(plot.y.label + scaleNote(plot.y.scale)) << "</text>\n";
  out << "</g>\n";

  // Series.
  std::vector<LabelBox> markers;
  std::vector<LabelRequest> labels;
  for (const Series& s : plot.series) {
    std::vector<const Point*> shown;
    for (const Point& p : s.points)
      if (usable(plot.x.scale, p.x) && usable(plot.y.scale, p.y)) shown.push_back(&p);
    if (shown.empty()) continue;
    out << "<g class=\"series";
    if (!s.cssClass.empty()) out << ' ' << escapeText(s.cssClass);
    out << "\" data-series=\""
        << escapeText(s.name) << "\">\n";
    if (s.line && shown.size() >= 2) {
      out << "<path fill=\"none\" stroke=\"" << escapeText(s.colour) << "\" stroke-width=\"1.6\""
          << (s.dashed ? " stroke-dasharray=\"5 4\"" : "") << " d=\"";
      for (std::size_t i = 0; i < shown.size(); ++i) {
        const double px = X(shown[i]->x), py = Y(shown[i]->y);
        if (i == 0) out << 'M' << num(px) << ' ' << num(py);
        else if (s.steps) out << " H" << num(px) << " V" << num(py);
        else out << " L" << num(px) << ' ' << num(py);
      }
      out << "\"/>\n";
    }
    for (const Point* p : shown) {
      const double px = X(p->x), py = Y(p->y);
      if (p->yLow && p->yHigh && usable(plot.y.scale, *p->yLow) && usable(plot.y.scale, *p->yHigh))
        out << "<line class=\"whisker\" x1=\"" << num(px) << "\" y1=\"" << num(Y(*p->yLow)) << "\" x2=\"" << num(px)
            << "\" y2=\"" << num(Y(*p->yHigh)) << "\" stroke=\"" << escapeText(s.colour) << "\" stroke-width=\"1\"/>\n";
      if (p->xLow && p->xHigh && usable(plot.x.scale, *p->xLow) && usable(plot.x.scale, *p->xHigh))
        out << "<line class=\"whisker\" x1=\"" << num(X(*p->xLow)) << "\" y1=\"" << num(py) << "\" x2=\""
            << num(X(*p->xHigh)) << "\" y2=\"" << num(py) << "\" stroke=\"" << escapeText(s.colour)
            << "\" stroke-width=\"1\"/>\n";
      const std::string& tooltip = p->title.empty() ? p->id : p->title;
      if (s.markers) {
        if (p->highlight)
          out << "<circle class=\"ring\" cx=\"" << num(px) << "\" cy=\"" << num(py)
              << "\" r=\"7.5\" fill=\"none\" stroke=\"#000\" stroke-width=\"1.5\"/>\n";
        out << "<circle class=\"pt" << (p->highlight ? " front" : "") << "\" data-point=\"" << escapeText(p->id)
            << "\" cx=\"" << num(px) << "\" cy=\"" << num(py) << "\" r=\"4\" fill=\"" << escapeText(s.colour)
            << "\"><title>" << escapeText(tooltip) << "</title></circle>\n";
        const double r = p->highlight ? 8.5 : 4.5;  // the ring's stroke included
        markers.push_back({px - r, py - r, px + r, py + r});
      }
      if (!p->label.empty()) labels.push_back({px, py, p->label, tooltip, p->highlight});
    }
    out << "</g>\n";
  }

  // Point labels (svg_labels.h): the front's first, then as many as fit,
  // none over another or over a point; one per group of points on one spot.
  out << "<g class=\"labels\" font-size=\"" << num(kLabelFontSize) << "\" font-family=\"monospace\">\n";
  for (const PlacedLabel& l : placeLabels(labels, markers, {x0, y0, x1, y1})) {
    if (l.leader) {
      const double lx = std::clamp(l.px, l.box.x0, l.box.x1), ly = std::clamp(l.py, l.box.y0, l.box.y1);
      out << "<line class=\"leader\" x1=\"" << num(l.px) << "\" y1=\"" << num(l.py) << "\" x2=\"" << num(lx)
          << "\" y2=\"" << num(ly) << "\" stroke=\"#999\" stroke-width=\"0.8\"/>\n";
    }
    out << "<text x=\"" << num(l.box.x0) << "\" y=\"" << num(l.box.y0 + kLabelBaseline) << "\""
        << (l.bold ? " font-weight=\"bold\"" : "")
        << "><title>" << escapeText(l.title) << "</title>" << escapeText(l.text) << "</text>\n";
  }
  out << "</g>\n";

  // Legend.
  out << "<g class=\"legend\" font-size=\"11\">\n";
  double ly = y0 + 8;
  for (const Series& s : plot.series) {
    if (s.name.empty()) continue;
    const double lx = x1 + 14;
    if (s.line)  // a scatter-only series: its marker alone
      out << "<line x1=\"" << num(lx) << "\" y1=\"" << num(ly) << "\" x2=\"" << num(lx + 18) << "\" y2=\""
          << num(ly) << "\" stroke=\"" << escapeText(s.colour) << "\" stroke-width=\"2\""
          << (s.dashed ? " stroke-dasharray=\"4 3\"" : "") << "/>";
    if (s.markers)
      out << "<circle cx=\"" << num(lx + 9) << "\" cy=\"" << num(ly) << "\" r=\"3.5\" fill=\""
          << escapeText(s.colour) << "\"/>";
    out << "<text x=\"" << num(lx + 24) << "\" y=\"" << num(ly) << "\" dy=\"4\">" << escapeText(s.name)
        << "</text>\n";
    ly += 17;
  }
  out << "</g>\n</svg>\n";
  return out.str();
}

Point pointAt(double x, double y) {
  Point p;
  p.x = x;
  p.y = y;
  return p;
}

void SeriesBuilder::add(const std::string& name, const SeriesStyle& style, Point point) {
  const auto [it, added] = index_.emplace(name, plot_.series.size());
  if (added) {
    Series s;
    s.name = name;
    s.colour = colour(style.colourIndex);
    s.line = style.line;
    s.dashed = style.dashed;
    plot_.series.push_back(s);
  }
  plot_.series[it->second].points.push_back(std::move(point));
}

void sortPointsByX(Plot& plot) {
  for (Series& s : plot.series)
    std::stable_sort(s.points.begin(), s.points.end(), [](const Point& a, const Point& b) { return a.x < b.x; });
}

}  // namespace reports::svg
