// SPEC 3.1-3.2's light terms as the shaders evaluate them: this header
// compiles shaders/light_terms.glsl, the very file the shaders include, as
// C++ templates on a number type. With double it is the exact reference
// value; with reference::FloatBound the bound a conformant float32
// evaluation stays within (reference/float_bound.h); the bound's tests add a
// float32 type with perturbed roundings. Nothing here restates a formula:
// the GLSL file is the one copy.
#pragma once

#include "reference/float_bound.h"

#include <algorithm>
#include <cmath>

namespace reference::terms {

// The shader's vec3, of any of those number types.
template <class T>
struct Vec3Of {
  T x, y, z;
};
template <class T>
Vec3Of<T> operator-(const Vec3Of<T>& a, const Vec3Of<T>& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
template <class T>
Vec3Of<T> operator-(const Vec3Of<T>& a) {
  return {-a.x, -a.y, -a.z};
}
template <class T>
Vec3Of<T> operator*(const Vec3Of<T>& a, const T& s) {
  return {a.x * s, a.y * s, a.z * s};
}

// The operations of admissible.glsl that light_terms.glsl calls, exact.
inline double clamp(double x, double low, double high) { return std::clamp(x, low, high); }
inline double max(double a, double b) { return std::max(a, b); }
inline double quotient(double a, double b) { return a / b; }
inline double inverseSqrt(double x) { return 1.0 / std::sqrt(x); }
inline double multiplyAdd(double a, double b, double c) { return a * b + c; }
inline double dotProduct(const Vec3Of<double>& a, const Vec3Of<double>& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline double mutantAttenuationPrecision(double x) { return x; }

// dot(a, b) bounded: inherited from a.x b.x + a.y b.y + a.z b.z in any order
// and with any contraction, so each product's inputs' errors and rounding,
// then two additions, each of a partial sum no larger than the sum of the
// products' magnitudes.
template <class P>
FloatBoundOf<P> dotProduct(const Vec3Of<FloatBoundOf<P>>& a, const Vec3Of<FloatBoundOf<P>>& b) {
  using F = FloatBoundOf<P>;
  const F products[3] = {a.x * b.x, a.y * b.y, a.z * b.z};
  F sum;
  double carried = 0, magnitudes = 0;
  for (const F& p : products) {
    sum.value += p.value;
    sum.lo += p.lo;
    sum.hi += p.hi;
    carried += p.error;
    magnitudes += p.largestResult();
  }
  sum.error = carried + 2.0 * F::rounding(P::kAddUlps, magnitudes);
  return sum;
}

// light_terms.glsl's dialect (its header says which).
#define LIGHTCTS_TERM template <class real>
#define real3 Vec3Of<real>
#define MUTANT_ACTIVE(name) false
#define SPOT_LIGHTS true
#include "shaders/light_terms.glsl"
#undef SPOT_LIGHTS
#undef MUTANT_ACTIVE
#undef real3
#undef LIGHTCTS_TERM

}  // namespace reference::terms
