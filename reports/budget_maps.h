// The pictures of `lightcts budget` (SPEC 5.5): reach and kept counts on one
// fixed colour scale (0, 1, 2, 4, 8, 16, 32, 64+) and the loss in false
// colour on a logarithmic scale, each with its legend drawn below the map
// (swatches and numbers in a small bitmap font), as 8-bit RGB.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace reports {

struct Rgb8Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;  // row 0 at the top
};

// The count scale's bin of `count`: 0, 1, 2-3, 4-7, 8-15, 16-31, 32-63, 64+.
int countBin(int count);
// The colour of a bin (0..7): dark grey for 0, then a viridis ramp.
void countBinColour(int bin, std::uint8_t rgb[3]);

// A count map (width x height counts, row 0 at the top) with its legend.
Rgb8Image countMap(int width, int height, const std::vector<int>& counts);
// |loss| in false colour, log10 over the decades [largest * 1e-4, largest];
// 0 (and what lies below) dark grey. The legend's ends carry the numbers.
Rgb8Image lossMap(int width, int height, const std::vector<double>& loss);
// Small count maps side by side, 2 pixels apart (an animated scene's frames).
Rgb8Image stripOf(const std::vector<Rgb8Image>& maps);

void writeRgb8Png(const std::string& path, const Rgb8Image& image);

}  // namespace reports
