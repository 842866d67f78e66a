// A number for bounding a float32 evaluation, operation by operation: the
// exact value, the range the exact value takes over its inputs' ranges
// (the points vertex snapping lets a pixel centre see), and a bound on how
// far a conformant float32 evaluation of the same operations may be from
// the exact value at the same point. Each operation widens the bound by its
// inputs' errors (exactly, not to first order: the product of two errors is
// kept) and by its own allowance from the precision table
// (reference/precision_table.h), taken at the largest magnitude the result
// may have; a factor that multiplies an error is taken at its largest over
// the range, so that at a kink (a saturate at 0, a range edge) the other
// factor's error is not multiplied by an exact 0. This is VK-GL-CTS's
// interval arithmetic (tcu::Interval with a FloatFormat) carried as an
// error beside an interval, for whole lighting terms.
//
// reference/light_terms.h evaluates shaders/light_terms.glsl with it; the
// shader's operations are its operations, so the bound follows the shader.
#pragma once

#include "reference/precision_table.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace reference {

template <class Precision = Float32Precision>
struct FloatBoundOf {
  using Self = FloatBoundOf;

  double value = 0;  // exact, at the centre
  double lo = 0, hi = 0;  // the exact value's range over the inputs' ranges
  double error = 0;  // |float32 result - exact value| anywhere in that range
  // No float result is below this: what a max() or clamp() with a constant
  // guarantees beyond lo - error (a divisor or an inversesqrt's input kept
  // off zero by max(x, 1e-5), however large x's error).
  double floor = -std::numeric_limits<double>::infinity();

  FloatBoundOf() = default;
  // A constant the shader writes, real(c): the exact c, and the rounding the
  // compiler gives the float32 literal (to nearest).
  FloatBoundOf(double constant)  // NOLINT: implicit, as a literal is in the shader
      : value(constant), lo(constant), hi(constant), error(std::abs(double(float(constant)) - constant)) {}
  // An input the shader reads: its exact value, how far the float it gets
  // may be, and the exact value's range (the value itself where it does not
  // vary over the snapping square).
  static Self input(double exact, double error) { return input(exact, error, exact, exact); }
  static Self input(double exact, double error, double low, double high) {
    Self x;
    x.value = exact;
    x.lo = std::min(low, exact);
    x.hi = std::max(high, exact);
    x.error = error;
    return x;
  }
  // A double the CPU rounds to float and uploads: the rounding is exact here.
  static Self uploaded(double exact) { return input(exact, std::abs(double(float(exact)) - exact)); }

  // The largest |exact value| over the range, and the largest |float result|.
  double largest() const { return std::max(std::abs(lo), std::abs(hi)); }
  double largestResult() const { return largest() + error; }
  // The smallest float result.
  double least() const { return std::max(lo - error, floor); }

  // x times an error: 0 where x is 0 whatever the error (an exact zero
  // factor keeps a product exactly 0).
  static double times(double x, double e) { return x == 0 ? 0.0 : x * e; }

  // An operation's own rounding, `ulps` of a result of magnitude up to m
  // (the ULP grows with the magnitude, so m's bounds every smaller result's),
  // and the flush of a denormal result.
  static double rounding(double ulps, double m) { return ulps * ulpAt(m) + Precision::kFlushFloor; }

  friend Self operator-(const Self& a) {
    Self r = a;
    r.value = -a.value;
    r.lo = -a.hi;
    r.hi = -a.lo;
    return r;
  }
  friend Self operator+(const Self& a, const Self& b) {
    Self r;
    r.value = a.value + b.value;
    r.lo = a.lo + b.lo;
    r.hi = a.hi + b.hi;
    const double carried = a.error + b.error;
    r.error = carried + rounding(Precision::kAddUlps, r.largest() + carried);
    return r;
  }
  friend Self operator-(const Self& a, const Self& b) { return a + (-b); }
  friend Self operator*(const Self& a, const Self& b) {
    Self r;
    r.value = a.value * b.value;
    const double ends[4] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
    r.lo = *std::min_element(ends, ends + 4);
    r.hi = *std::max_element(ends, ends + 4);
    const double carried = times(a.largest(), b.error) + times(b.largest(), a.error) + times(a.error, b.error);
    r.error = carried + rounding(Precision::kMultiplyUlps, r.largest() + carried);
    return r;
  }
  Self& operator*=(const Self& b) { return *this = *this * b; }

  // a / b. Where b's float may be 0 the quotient is unbounded.
  friend Self quotient(const Self& a, const Self& b) {
    Self r;
    const double smallestDivisor = b.lo > 0 ? b.least() : b.hi < 0 ? -b.hi - b.error : 0.0;
    r.value = a.value / b.value;
    if (!(smallestDivisor > 0)) {
      r.lo = -std::numeric_limits<double>::infinity();
      r.hi = std::numeric_limits<double>::infinity();
      r.error = std::numeric_limits<double>::infinity();
      return r;
    }
    const double ends[4] = {a.lo / b.lo, a.lo / b.hi, a.hi / b.lo, a.hi / b.hi};
    r.lo = *std::min_element(ends, ends + 4);
    r.hi = *std::max_element(ends, ends + 4);
    // (a + da) / (b + db) - a / b = (da - (a / b) db) / (b + db).
    const double carried = (a.error + times(r.largest(), b.error)) / smallestDivisor;
    r.error = carried + rounding(Precision::kQuotientUlps, r.largest() + carried);
    return r;
  }

  // 1 / sqrt(x), decreasing and convex: the input's error moves it most at
  // the smallest x it may be.
  friend Self inverseSqrt(const Self& x) {
    Self r;
    const double lowest = x.least();
    r.value = 1.0 / std::sqrt(x.value);
    if (!(lowest > 0)) {
      r.lo = 0;
      r.hi = r.error = std::numeric_limits<double>::infinity();
      return r;
    }
    r.lo = 1.0 / std::sqrt(x.hi);
    r.hi = 1.0 / std::sqrt(x.lo);
    const double carried = 1.0 / std::sqrt(lowest) - r.hi;
    r.error = carried + rounding(Precision::kInverseSqrtUlps, r.hi + carried);
    return r;
  }

  // clamp(x, low, high), max(a, b): "correct result", and 1-Lipschitz; a
  // clamp whose input stays beyond one end (errors included) is exact.
  friend Self clamp(const Self& x, const Self& low, const Self& high) {
    Self r;
    r.value = std::clamp(x.value, low.value, high.value);
    r.lo = std::clamp(x.lo, low.value, high.value);
    r.hi = std::clamp(x.hi, low.value, high.value);
    const bool pinned = x.lo - x.error >= high.value + high.error || x.hi + x.error <= low.value - low.error;
    r.error = pinned ? std::max(low.error, high.error) : std::max({x.error, low.error, high.error});
    // Both the float result and the exact one lie within the ends.
    r.error = std::min(r.error, (high.value + high.error) - (low.value - low.error));
    r.floor = std::max(x.least(), low.value - low.error);
    return r;
  }
  friend Self max(const Self& a, const Self& b) {
    Self r;
    r.value = std::max(a.value, b.value);
    r.lo = std::max(a.lo, b.lo);
    r.hi = std::max(a.hi, b.hi);
    r.error = a.lo - a.error > b.hi + b.error   ? a.error
              : b.lo - b.error > a.hi + a.error ? b.error
                                                : std::max(a.error, b.error);
    r.floor = std::max(a.least(), b.least());
    return r;
  }

  // a * b + c, fused or not (a fused one rounds once, within this bound).
  friend Self multiplyAdd(const Self& a, const Self& b, const Self& c) { return a * b + c; }

  // The test-only mutant's rounding through 16 bits is not the model's.
  friend Self mutantAttenuationPrecision(const Self& x) { return x; }
};

using FloatBound = FloatBoundOf<>;

}  // namespace reference
