// The precision table: how far a conformant implementation's float32
// result of each operation may be from the exact result of its float32
// inputs, as the APIs' specifications state it (Vulkan's "Precision and
// Operation of SPIR-V Instructions"; GLSL 4.60 4.7.1 says the same for
// OpenGL). reference/float_bound.h bounds a whole expression operation by
// operation from these entries and nothing else; docs/tolerances.md quotes
// the sentences.
//
// ULPs are relative to the exact result: one ULP of a normal x is at most
// 2^-23 |x| (ulpRelative), twice float32's unit roundoff.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>

namespace reference {

struct Float32Precision {
  // x + y, x - y, x * y: "correctly rounded", and without the
  // RoundingModeRTE execution mode (none of lightcts's shaders declares
  // one) that means either neighbour of the exact result: under 1 ULP.
  // Conversions (an uploaded double rounded to float, a literal) likewise.
  static constexpr double kAddUlps = 1;
  static constexpr double kMultiplyUlps = 1;
  // x / y: 2.5 ULP; and an operation not decorated NoContraction may be
  // computed as x * (1 / y) (Vulkan's AllowRecip): 2.5 ULP for the
  // reciprocal, then 1 for the product.
  static constexpr double kQuotientUlps = 3.5;
  // inversesqrt: 2 ULP; normalize is inherited from x * inversesqrt(dot(x, x)).
  static constexpr double kInverseSqrtUlps = 2;
  // Any denormal input or result may be flushed to zero: an absolute
  // error of up to the smallest normal float on every result.
  static constexpr double kFlushFloor = 0x1p-126;
};

// One ULP of a normal float32 x, relative: at most 2^-23 |x|.
constexpr double kUlpRelative = 0x1p-23;

// Vulkan's ulp(x) at a magnitude |x| >= 0: the gap between the two floats
// around x, 2^(e - 23) for |x| in [2^e, 2^(e+1)), 2^-149 below the normals;
// past the floats (2^128 and up, infinity) and for NaN the magnitude itself.
inline double ulpAt(double magnitude) {
  if (!(magnitude < 0x1p128)) return magnitude;
  if (magnitude < 0x1p-126) return 0x1p-149;
  // 2^e is magnitude's exponent bits alone (a normal double); read from the
  // bits, since frexp and ldexp are library calls on the reference's hottest path.
  const double power = std::bit_cast<double>(std::bit_cast<std::uint64_t>(magnitude) & 0x7ff0000000000000u);
  return power * 0x1p-23;
}

}  // namespace reference
