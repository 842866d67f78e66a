#include "comparison/image_comparison.h"

#include "comparison/vacuous_comparison.h"
#include "reference/tolerance_model.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>

namespace comparison {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

std::string sizeOf(const imaging::Image& image) {
  return std::to_string(image.width) + "x" + std::to_string(image.height);
}

void requireChannels(const imaging::Image& image, const char* what, int a, int b, const char* meaning) {
  if (image.channels != a && image.channels != b)
    throw std::invalid_argument(std::string("compareImages: ") + what + " must have " + meaning + ", it has " +
                                std::to_string(image.channels) + " channels");
}

// The Image constructor keeps pixels and dimensions in step, but the members
// are public; a mismatch here would read out of bounds.
void requireStorage(const imaging::Image& image, const char* what) {
  const std::size_t expected = std::size_t(image.width) * image.height * image.channels;
  if (image.width < 0 || image.height < 0 || image.pixels.size() != expected)
    throw std::invalid_argument(std::string("compareImages: ") + what + " (" + sizeOf(image) + "x" +
                                std::to_string(image.channels) + ") holds " + std::to_string(image.pixels.size()) +
                                " floats instead of " + std::to_string(expected));
}

void validate(const imaging::Image& result, const reference::ReferenceImages& reference, int worstCount) {
  if (worstCount < 0) throw std::invalid_argument("compareImages: worstCount must not be negative");
  requireChannels(result, "the result", 3, 4, "3 or 4 channels (RGB or RGBA)");
  requireChannels(reference.value, "the reference value", 4, 4, "4 channels (RGB and mask)");
  requireChannels(reference.tolerance, "the tolerance", 3, 3, "3 channels (RGB)");
  const imaging::Image& value = reference.value;
  const imaging::Image& tolerance = reference.tolerance;
  if (result.width != value.width || result.height != value.height || tolerance.width != value.width ||
      tolerance.height != value.height)
    throw std::invalid_argument("compareImages: image sizes differ: result " + sizeOf(result) + ", reference " +
                                sizeOf(value) + ", tolerance " + sizeOf(tolerance));
  requireStorage(result, "the result");
  requireStorage(value, "the reference value");
  requireStorage(tolerance, "the tolerance");
}

// The order of Comparison::worst: largest excess first, then by row, then column.
bool ranksBefore(const PixelReport& a, const PixelReport& b) {
  if (a.excess != b.excess) return a.excess > b.excess;
  return a.y != b.y ? a.y < b.y : a.x < b.x;
}

// Keeps the `capacity` worst pixels in a heap whose top is the least bad kept,
// so memory stays bounded when every pixel of a large image fails.
class WorstPixels {
 public:
  explicit WorstPixels(std::size_t capacity) : capacity_(capacity) {}

  void offer(const PixelReport& pixel) {
    if (heap_.size() < capacity_) {
      heap_.push_back(pixel);
      std::push_heap(heap_.begin(), heap_.end(), ranksBefore);
    } else if (capacity_ > 0 && ranksBefore(pixel, heap_.front())) {
      std::pop_heap(heap_.begin(), heap_.end(), ranksBefore);
      heap_.back() = pixel;
      std::push_heap(heap_.begin(), heap_.end(), ranksBefore);
    }
  }

  std::vector<PixelReport> sorted() && {
    std::sort_heap(heap_.begin(), heap_.end(), ranksBefore);
    return std::move(heap_);
  }

 private:
  std::size_t capacity_;
  std::vector<PixelReport> heap_;
};

void paint(imaging::Image& mask, int x, int y, float r, float g, float b) {
  mask.at(x, y, 0) = r;
  mask.at(x, y, 1) = g;
  mask.at(x, y, 2) = b;
}

}  // namespace

Comparison compareImages(const imaging::Image& result, const reference::ReferenceImages& reference,
                         const lighting::Expectation& expect, int worstCount) {
  validate(result, reference, worstCount);
  const imaging::Image& value = reference.value;
  const imaging::Image& tolerance = reference.tolerance;

  Comparison out;
  out.width = result.width;
  out.height = result.height;
  out.maxFailingPixels = expect.maxFailingPixels;
  out.toleranceScale = expect.toleranceScale;
  out.expectFail = expect.expectFail;
  out.errorMask = imaging::Image(result.width, result.height, 3);

  WorstPixels worst{std::size_t(worstCount)};
  double sumOfSquares = 0;
  long long samples = 0;
  for (int y = 0; y < result.height; ++y) {
    for (int x = 0; x < result.width; ++x) {
      const bool masked = value.at(x, y, 3) == 0.0f;
      ++(masked ? out.maskedPixels : out.comparedPixels);
      if (!masked && (value.at(x, y, 0) > reference::tolerance::kFlushToZeroFloor ||
                      value.at(x, y, 1) > reference::tolerance::kFlushToZeroFloor ||
                      value.at(x, y, 2) > reference::tolerance::kFlushToZeroFloor))
        ++out.litComparedPixels;

      bool nonFinite = false;
      for (int c = 0; c < result.channels; ++c) nonFinite = nonFinite || !std::isfinite(result.at(x, y, c));

      PixelReport pixel{x, y};
      pixel.nonFinite = nonFinite;
      pixel.excess = -kInfinity;
      bool outOfTolerance = false;
      for (int c = 0; c < 3; ++c) {
        pixel.result[c] = result.at(x, y, c);
        pixel.reference[c] = value.at(x, y, c);
        pixel.tolerance[c] = tolerance.at(x, y, c);
        // In double, where the difference of two floats is exact: a result
        // off by exactly the tolerance passes.
        const double difference = std::abs(double(pixel.result[c]) - double(pixel.reference[c]));
        const double bound = double(pixel.tolerance[c]) * expect.toleranceScale;
        // Written so that a NaN anywhere (result, reference or tolerance) fails.
        outOfTolerance = outOfTolerance || !(difference <= bound);
        // std::max would drop a NaN; it ranks as the worst instead, and keeps
        // the ordering of `worst` well defined.
        const double over = difference - bound;
        pixel.excess = std::isnan(over) ? kInfinity : std::max(pixel.excess, over);
        if (masked || nonFinite) continue;
        out.maxAbsError = std::max(out.maxAbsError, difference);
        const double ratio = bound > 0 ? difference / bound : (difference > 0 ? kInfinity : 0.0);
        out.maxErrorOverTolerance = std::max(out.maxErrorOverTolerance, ratio);
        sumOfSquares += difference * difference;
        ++samples;
      }
      if (nonFinite) pixel.excess = kInfinity;

      if (nonFinite) {
        ++out.nonFinitePixels;
        paint(out.errorMask, x, y, 1, 0, 1);
      } else if (masked) {
        paint(out.errorMask, x, y, 0.25f, 0.25f, 0.25f);
      } else if (outOfTolerance) {
        paint(out.errorMask, x, y, 1, 0, 0);
      }
      if (!reference.shadowInterval.pixels.empty() && reference.shadowInterval.at(x, y, 2) != 0.0f) {
        pixel.shadowed = true;
        pixel.shadowLo = reference.shadowInterval.at(x, y, 0);
        pixel.shadowHi = reference.shadowInterval.at(x, y, 1);
      }
      if (nonFinite || (!masked && outOfTolerance)) {
        ++out.failingPixels;
        worst.offer(pixel);
      }
    }
  }

  out.rmse = samples > 0 ? std::sqrt(sumOfSquares / double(samples)) : 0.0;
  out.worst = std::move(worst).sorted();
  out.comparisonPassed = out.failingPixels <= expect.maxFailingPixels && out.nonFinitePixels == 0;
  out.shadowedPixels = reference.shadowedPixels;
  out.ambiguousShadowPixels = reference.ambiguousShadowPixels;
  out.defectiveScene = reference.shadowAmbiguityExceedsCap();
  const bool asExpected = out.comparisonPassed != out.expectFail && out.nonFinitePixels == 0 && !out.defectiveScene;
  out.qualityWarning = vacuousComparisonReason(
      {(long long)(result.width) * result.height, out.comparedPixels, out.litComparedPixels});
  out.verdict = !asExpected ? Verdict::Fail : out.qualityWarning.empty() ? Verdict::Pass : Verdict::QualityWarning;
  return out;
}

}  // namespace comparison
