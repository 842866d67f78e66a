// A float32 number whose every operation returns one result a conformant
// implementation may return, drawn at random: the exact result of its float
// inputs, moved as far as the precision table allows (reference/
// precision_table.h): either neighbour of a sum or product, a quotient within
// 3.5 ULP, an inversesqrt within 2, a multiply-add fused or not, a dot
// product summed in any order, a denormal result flushed or kept. The light
// terms' property tests (light_terms_property_test.cpp) evaluate
// shaders/light_terms.glsl with it, through reference/light_terms.h, and
// hold the results to the FloatBound of the same operations.
#pragma once

#include "reference/light_terms.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

namespace reference::perturbed {

// The random source of the evaluation under way; one per test, seeded.
class Perturbation {
 public:
  explicit Perturbation(std::uint64_t seed) : rng_(seed) {}
  bool coin() { return std::uniform_int_distribution<int>(0, 1)(rng_) == 1; }
  // The next evaluation's operations all err upwards (+1), all downwards
  // (-1), or each its own way (0): the bound is reached where the errors
  // line up, which random directions alone seldom do.
  void lean(int direction) { lean_ = direction; }
  // A fraction of an allowance in [-1, 1]: the lean's end, or drawn, mostly
  // at an end.
  double fraction() {
    if (lean_ != 0) return double(lean_);
    const int pick = std::uniform_int_distribution<int>(0, 9)(rng_);
    if (pick < 4) return -1.0;
    if (pick < 8) return 1.0;
    return std::uniform_real_distribution<double>(-1.0, 1.0)(rng_);
  }
  // Which neighbour a rounding takes: the upper one under an upward lean.
  bool upper() { return lean_ != 0 ? lean_ > 0 : coin(); }
  std::mt19937_64& engine() { return rng_; }

 private:
  std::mt19937_64 rng_;
  int lean_ = 0;
};

// The Perturbation the operations draw from (set for each evaluation).
inline Perturbation*& current() {
  static Perturbation* active = nullptr;
  return active;
}

// The gap between the floats around x (Vulkan's ulp(x)), written apart from
// reference::ulpAt, which the bounds under test use.
inline double ulpOf(double x) {
  const double a = std::abs(x);
  if (a < 0x1p-126) return 0x1p-149;
  int exponent = 0;
  std::frexp(a, &exponent);  // a in [2^(exponent-1), 2^exponent)
  return std::ldexp(1.0, exponent - 1 - 23);
}

// A float within `ulps` ULP of the exact x, the offset drawn by fraction();
// a denormal result may be flushed to zero.
inline float within(double x, double ulps) {
  Perturbation& p = *current();
  const double target = x + p.fraction() * ulps * ulpOf(x);
  // Round towards x so the float stays within the allowance.
  float f = float(target);
  if (std::abs(double(f) - x) > ulps * ulpOf(x)) f = std::nextafter(f, float(x));
  if (std::abs(double(f)) < 0x1p-126 && p.coin()) f = 0.0f;
  return f;
}

// Either neighbour of the exact x ("correctly rounded" in an
// implementation-defined rounding mode).
inline float faithful(double x) {
  Perturbation& p = *current();
  float f = float(x);
  if (double(f) != x) {
    const float below = double(f) < x ? f : std::nextafter(f, -INFINITY);
    const float above = double(f) > x ? f : std::nextafter(f, INFINITY);
    f = p.upper() ? above : below;
  }
  if (std::abs(double(f)) < 0x1p-126 && p.coin()) f = 0.0f;
  return f;
}

struct Perturbed {
  float v = 0;
  Perturbed() = default;
  Perturbed(double constant) : v(float(constant)) {}  // NOLINT: a literal, rounded by the compiler
  static Perturbed of(float f) {
    Perturbed r;
    r.v = f;
    return r;
  }

  friend Perturbed operator-(Perturbed a) { return of(-a.v); }
  friend Perturbed operator+(Perturbed a, Perturbed b) { return of(faithful(double(a.v) + double(b.v))); }
  friend Perturbed operator-(Perturbed a, Perturbed b) { return of(faithful(double(a.v) - double(b.v))); }
  friend Perturbed operator*(Perturbed a, Perturbed b) { return of(faithful(double(a.v) * double(b.v))); }
  Perturbed& operator*=(Perturbed b) { return *this = *this * b; }
  friend Perturbed quotient(Perturbed a, Perturbed b) {
    return of(within(double(a.v) / double(b.v), Float32Precision::kQuotientUlps));
  }
  friend Perturbed inverseSqrt(Perturbed x) {
    return of(within(1.0 / std::sqrt(double(x.v)), Float32Precision::kInverseSqrtUlps));
  }
  friend Perturbed clamp(Perturbed x, Perturbed low, Perturbed high) { return of(std::clamp(x.v, low.v, high.v)); }
  friend Perturbed max(Perturbed a, Perturbed b) { return of(std::max(a.v, b.v)); }
  // Fused (one rounding of the exact a b + c) or two roundings.
  friend Perturbed multiplyAdd(Perturbed a, Perturbed b, Perturbed c) {
    if (current()->coin()) return of(faithful(double(a.v) * double(b.v) + double(c.v)));
    return a * b + c;
  }
  friend Perturbed mutantAttenuationPrecision(Perturbed x) { return x; }
};

// dot(a, b): the three products summed in a random order, each addition
// fused with its product or not.
inline Perturbed dotProduct(const terms::Vec3Of<Perturbed>& a, const terms::Vec3Of<Perturbed>& b) {
  std::array<std::pair<Perturbed, Perturbed>, 3> pairs = {{{a.x, b.x}, {a.y, b.y}, {a.z, b.z}}};
  std::shuffle(pairs.begin(), pairs.end(), current()->engine());
  Perturbed sum = pairs[0].first * pairs[0].second;
  for (int i = 1; i < 3; ++i) sum = multiplyAdd(pairs[i].first, pairs[i].second, sum);
  return sum;
}

}  // namespace reference::perturbed
