// SPEC 7: a comparison must be able to fail. A frame whose reference is
// black on every compared pixel, or whose compared pixels are too few,
// proves nothing by matching: its verdict is QualityWarning, with the reason
// this file words, never Pass (docs/tolerances.md, "A comparison that
// checks nothing").
#pragma once

#include <string>

namespace comparison {

// The smallest share of a frame's pixels that must be compared (mask != 0)
// for a match to count. 1%: the suite's scenes mask at most a few percent
// (edges, ambiguous shadow texels), while a frame masked all but a sliver
// says nothing about the model.
inline constexpr double kMinimumComparedShare = 0.01;

struct PixelCounts {
  long long total = 0;        // width * height
  long long compared = 0;     // mask != 0
  long long litCompared = 0;  // compared, and some channel of the reference above the flush-to-zero floor
};

// Why a frame with these counts checks nothing, or "" when it checks something.
std::string vacuousComparisonReason(const PixelCounts& counts);

}  // namespace comparison
