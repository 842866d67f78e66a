#include "reports/budget_maps.h"

#include "imaging/image_files.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>

namespace reports {
namespace {

// A 3x5 bitmap font for the legends' numbers: each glyph five rows of three
// bits, the high bit on the left.
const std::map<char, std::array<std::uint8_t, 5>>& glyphs() {
  static const std::map<char, std::array<std::uint8_t, 5>> font = {
      {'0', {7, 5, 5, 5, 7}}, {'1', {2, 6, 2, 2, 7}}, {'2', {7, 1, 7, 4, 7}}, {'3', {7, 1, 7, 1, 7}},
      {'4', {5, 5, 7, 1, 1}}, {'5', {7, 4, 7, 1, 7}}, {'6', {7, 4, 7, 5, 7}}, {'7', {7, 1, 1, 1, 1}},
      {'8', {7, 5, 7, 5, 7}}, {'9', {7, 5, 7, 1, 7}}, {'+', {0, 2, 7, 2, 0}}, {'-', {0, 0, 7, 0, 0}},
      {'.', {0, 0, 0, 0, 2}}, {'e', {0, 7, 7, 4, 7}}, {' ', {0, 0, 0, 0, 0}},
  };
  return font;
}

constexpr int kGlyphWidth = 4;  // 3 pixels and a gap
constexpr int kLegendHeight = 18;
constexpr std::uint8_t kText[3] = {230, 230, 230};
constexpr std::uint8_t kBackground[3] = {16, 16, 16};

int textWidth(const std::string& text) { return int(text.size()) * kGlyphWidth; }

void setPixel(Rgb8Image& image, int x, int y, const std::uint8_t rgb[3]) {
  if (x < 0 || y < 0 || x >= image.width || y >= image.height) return;
  std::copy(rgb, rgb + 3, image.rgb.begin() + (std::size_t(y) * image.width + x) * 3);
}

void drawText(Rgb8Image& image, int x, int y, const std::string& text) {
  for (char c : text) {
    const auto glyph = glyphs().find(c);
    if (glyph != glyphs().end())
      for (int row = 0; row < 5; ++row)
        for (int col = 0; col < 3; ++col)
          if (glyph->second[std::size_t(row)] & (4 >> col)) setPixel(image, x + col, y + row, kText);
    x += kGlyphWidth;
  }
}

void fillRect(Rgb8Image& image, int x, int y, int w, int h, const std::uint8_t rgb[3]) {
  for (int j = y; j < y + h; ++j)
    for (int i = x; i < x + w; ++i) setPixel(image, i, j, rgb);
}

// A map of width x height above a legend band; the image is at least as wide as the legend.
Rgb8Image withLegendBand(int width, int height, int legendWidth) {
  Rgb8Image image;
  image.width = std::max(width, legendWidth);
  image.height = height + kLegendHeight;
  image.rgb.resize(std::size_t(image.width) * image.height * 3);
  for (std::size_t p = 0; p < image.rgb.size(); p += 3) std::copy(kBackground, kBackground + 3, image.rgb.begin() + p);
  return image;
}

// viridis at eight points (matplotlib's table, evenly spaced).
constexpr std::uint8_t kRamp[8][3] = {{68, 1, 84},    {70, 50, 127},  {54, 92, 141},  {39, 127, 142},
                                      {31, 161, 135}, {74, 193, 109}, {160, 218, 57}, {253, 231, 37}};
constexpr std::uint8_t kZero[3] = {40, 40, 40};

void rampColour(double t, std::uint8_t rgb[3]) {
  t = std::clamp(t, 0.0, 1.0) * 7;
  const int i = std::min(int(t), 6);
  const double f = t - i;
  for (int c = 0; c < 3; ++c) rgb[c] = std::uint8_t(std::lround(kRamp[i][c] * (1 - f) + kRamp[i + 1][c] * f));
}

std::string shortNumber(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1e", v);
  std::string s = text;
  // "2.3e-05" -> "2.3e-5": the legend is narrow.
  const auto e = s.find('e');
  if (e != std::string::npos) {
    std::string exponent = s.substr(e + 1);
    const bool negative = exponent[0] == '-';
    exponent = exponent.substr(1);
    while (exponent.size() > 1 && exponent[0] == '0') exponent.erase(0, 1);
    s = s.substr(0, e) + "e" + (negative ? "-" : "") + exponent;
  }
  return s;
}

}  // namespace

int countBin(int count) {
  if (count <= 0) return 0;
  int bin = 1;
  for (int edge = 2; edge <= 64 && count >= edge; edge *= 2) ++bin;
  return std::min(bin, 7);
}

void countBinColour(int bin, std::uint8_t rgb[3]) {
  if (bin <= 0) {
    std::copy(kZero, kZero + 3, rgb);
    return;
  }
  rampColour((bin - 1) / 6.0, rgb);
}

Rgb8Image countMap(int width, int height, const std::vector<int>& counts) {
  static const char* const kLabels[8] = {"0", "1", "2", "4", "8", "16", "32", "64+"};
  constexpr int kSwatch = 14;  // each bin's swatch and label column
  Rgb8Image image = withLegendBand(width, height, 8 * kSwatch + 2);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      std::uint8_t rgb[3];
      countBinColour(countBin(counts[std::size_t(y) * width + x]), rgb);
      setPixel(image, x, y, rgb);
    }
  for (int bin = 0; bin < 8; ++bin) {
    std::uint8_t rgb[3];
    countBinColour(bin, rgb);
    fillRect(image, 1 + bin * kSwatch, height + 2, kSwatch - 2, 6, rgb);
    drawText(image, 1 + bin * kSwatch, height + 11, kLabels[bin]);
  }
  return image;
}

Rgb8Image lossMap(int width, int height, const std::vector<double>& loss) {
  double largest = 0;
  for (double v : loss)
    if (std::isfinite(v)) largest = std::max(largest, std::abs(v));
  const double smallest = largest * 1e-4;
  const std::string low = shortNumber(smallest), high = shortNumber(largest);
  constexpr int kBar = 64;
  Rgb8Image image = withLegendBand(width, height, kBar + 2);
  const auto colourOf = [&](double v, std::uint8_t rgb[3]) {
    v = std::abs(v);
    if (!(largest > 0) || !(v > smallest) || !std::isfinite(v)) {
      std::copy(kZero, kZero + 3, rgb);
      return;
    }
    rampColour(std::log10(v / smallest) / 4.0, rgb);
  };
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      std::uint8_t rgb[3];
      colourOf(loss[std::size_t(y) * width + x], rgb);
      setPixel(image, x, y, rgb);
    }
  for (int i = 0; i < kBar; ++i) {
    std::uint8_t rgb[3];
    rampColour(i / double(kBar - 1), rgb);
    fillRect(image, 1 + i, height + 2, 1, 6, rgb);
  }
  drawText(image, 1, height + 11, largest > 0 ? low : "0");
  if (largest > 0) drawText(image, std::max(1 + kBar - textWidth(high), 1 + textWidth(low) + 4), height + 11, high);
  return image;
}

Rgb8Image stripOf(const std::vector<Rgb8Image>& maps) {
  Rgb8Image strip;
  for (const Rgb8Image& m : maps) {
    strip.width += m.width + 2;
    strip.height = std::max(strip.height, m.height);
  }
  strip.rgb.assign(std::size_t(strip.width) * strip.height * 3, 0);
  int x0 = 0;
  for (const Rgb8Image& m : maps) {
    for (int y = 0; y < m.height; ++y)
      std::copy(m.rgb.begin() + std::size_t(y) * m.width * 3, m.rgb.begin() + std::size_t(y + 1) * m.width * 3,
                strip.rgb.begin() + (std::size_t(y) * strip.width + x0) * 3);
    x0 += m.width + 2;
  }
  return strip;
}

void writeRgb8Png(const std::string& path, const Rgb8Image& image) {
  imaging::writePng8(path, image.width, image.height, 3, image.rgb);
}

}  // namespace reports
