// The operations whose precision the APIs leave open, each written once, so
// that an admissible variant (SPEC 7; shaders/shader_interface.def) pushes
// that freedom to its bound wherever the model uses it. The stages are built
// twice (shaders/CMakeLists.txt): the model's build, which every shipped
// pipeline uses, has LIGHTCTS_ADMISSIBLE_VARIANTS 0, so each function is the
// plain operation and no variant's code is in its SPIR-V (SwiftShader compiles
// what a specialization constant would switch off, several times the
// pipeline's time); the variants' build has the code, chosen by the ADMISSIBLE constant
// (a Vulkan variant pipeline gets it with that choice folded in,
// shaders/spirv_constant_folding.h).
//
// shaders/light_terms.glsl calls these by name, and the reference
// (reference/light_terms.h) gives the same names its own meanings: the
// exact operation, and its bound from the precision table.
#ifndef LIGHTCTS_ADMISSIBLE_GLSL
#define LIGHTCTS_ADMISSIBLE_GLSL

#include "shader_interface.glsl"

#if LIGHTCTS_ADMISSIBLE_VARIANTS
// x moved `steps` representable floats towards +infinity (towards -infinity
// for steps < 0), never past zero nor to an infinity; zero, infinities and
// NaN stay as they are. A step across a power of two is twice as long as
// the one before it, so x moves by at most |steps| times the gap next to it
// in that direction: a driver result within half a ULP then lands within
// |steps| + 1/2 ULP of the exact one. Written without branches: lavapipe
// 22.3 crashes while drawing a deferred light pass that calls this function
// written with early returns for each component of its position.
float floatSteps(float x, int steps) {
  float ax = abs(x);
  bool unmoved = steps == 0 || ax == 0.0 || !(ax <= 3.4028235e38);  // zero, infinity or NaN
  uint magnitude = floatBitsToUint(ax);
  bool away = (x > 0.0) == (steps > 0);  // the magnitude grows
  float gap = abs(uintBitsToFloat(away ? magnitude + 1u : magnitude - 1u) - ax);
  float limit = float(abs(steps)) * gap;
  float target = max(away ? ax + limit : ax - limit, 0.0);
  uint moved = min(floatBitsToUint(target), 0x7f7fffffu);
  // The sum rounds to nearest: one step back where it went past the limit.
  moved = abs(uintBitsToFloat(moved) - ax) > limit ? (away ? moved - 1u : moved + 1u) : moved;
  float result = uintBitsToFloat((floatBitsToUint(x) & 0x80000000u) | moved);
  return unmoved ? x : result;
}
#endif

// Denormals flushed (the denormals-flushed variant): GPUs may flush any
// value below the smallest normal float, 2^-126, to zero.
float flushed(float x) {
#if LIGHTCTS_ADMISSIBLE_VARIANTS
  if (ADMISSIBLE == ADMISSIBLE_DENORMALS_FLUSHED && abs(x) < 1.17549435e-38) return 0.0;
#endif
  return x;
}
vec3 flushed(vec3 v) { return vec3(flushed(v.x), flushed(v.y), flushed(v.z)); }

// a / b: 2.5 ULP (the quotient variants move the driver's result 2 ULP).
float quotient(float a, float b) {
  float q = a / b;
#if LIGHTCTS_ADMISSIBLE_VARIANTS
  if (ADMISSIBLE == ADMISSIBLE_QUOTIENT_UP) return floatSteps(q, 2);
  if (ADMISSIBLE == ADMISSIBLE_QUOTIENT_DOWN) return floatSteps(q, -2);
#endif
  return flushed(q);
}
vec2 quotient(vec2 a, vec2 b) { return vec2(quotient(a.x, b.x), quotient(a.y, b.y)); }
vec2 quotient(vec2 a, float b) { return quotient(a, vec2(b)); }
vec3 quotient(vec3 a, float b) { return vec3(quotient(a.x, b), quotient(a.y, b), quotient(a.z, b)); }

// inversesqrt: 2 ULP (the variants move the driver's result 1 ULP, the
// nearest whole step that stays legal for a correctly rounded driver).
float inverseSqrt(float x) {
  float r = inversesqrt(x);
#if LIGHTCTS_ADMISSIBLE_VARIANTS
  if (ADMISSIBLE == ADMISSIBLE_INVERSESQRT_UP) return floatSteps(r, 1);
  if (ADMISSIBLE == ADMISSIBLE_INVERSESQRT_DOWN) return floatSteps(r, -1);
#endif
  return flushed(r);
}

// The products and sums a compiler may contract: a * b + c as one fused
// operation or two roundings (the mad variants force each; the model leaves
// it to the driver). GLSL 330 has neither fma nor `precise`: on OpenGL both
// variants are the model (shader_interface.def: vulkan only).
float multiplyAdd(float a, float b, float c) {
#if LIGHTCTS_ADMISSIBLE_VARIANTS
  if (ADMISSIBLE == ADMISSIBLE_MAD_FUSED) return fma(a, b, c);
  if (ADMISSIBLE == ADMISSIBLE_MAD_UNFUSED) {
    precise float product = a * b;
    precise float sum = product + c;
    return sum;
  }
#endif
  return flushed(a * b + c);
}

// dot(a, b), inherited from a.x b.x + a.y b.y + a.z b.z in any order.
float dotProduct(vec3 a, vec3 b) {
#if LIGHTCTS_ADMISSIBLE_VARIANTS
  if (ADMISSIBLE == ADMISSIBLE_MAD_FUSED) return fma(a.z, b.z, fma(a.y, b.y, a.x * b.x));
  if (ADMISSIBLE == ADMISSIBLE_MAD_UNFUSED) {
    precise float xx = a.x * b.x;
    precise float yy = a.y * b.y;
    precise float zz = a.z * b.z;
    precise float sum = xx + yy;
    precise float total = sum + zz;
    return total;
  }
#endif
  return flushed(dot(a, b));
}

// normalize(v), inherited from v * inversesqrt(dot(v, v)): the inversesqrt
// variants move its inversesqrt.
vec3 unitVector(vec3 v) {
#if LIGHTCTS_ADMISSIBLE_VARIANTS
  if (ADMISSIBLE == ADMISSIBLE_INVERSESQRT_UP || ADMISSIBLE == ADMISSIBLE_INVERSESQRT_DOWN)
    return v * inverseSqrt(dotProduct(v, v));
#endif
  return normalize(v);
}

// exp2(x): 3 + 2|x| ULP (the variants move the driver's result by the whole
// ULPs below 2.5 + 2|x|).
float power2(float x) {
  float r = exp2(x);
#if LIGHTCTS_ADMISSIBLE_VARIANTS
  int steps = int(floor(2.5 + 2.0 * abs(x)));
  if (ADMISSIBLE == ADMISSIBLE_EXP2_LOG2_UP) return floatSteps(r, steps);
  if (ADMISSIBLE == ADMISSIBLE_EXP2_LOG2_DOWN) return floatSteps(r, -steps);
#endif
  return r;
}
vec3 power2(vec3 x) { return vec3(power2(x.x), power2(x.y), power2(x.z)); }

// log2(x): 3 ULP outside [0.5, 2], 2^-21 absolute inside (the variants move
// the driver's result 2 ULP, or 2^-22 inside).
float logarithm2(float x) {
  float r = log2(x);
#if LIGHTCTS_ADMISSIBLE_VARIANTS
  bool up = ADMISSIBLE == ADMISSIBLE_EXP2_LOG2_UP, down = ADMISSIBLE == ADMISSIBLE_EXP2_LOG2_DOWN;
  if (!up && !down) return r;
  if (x >= 0.5 && x <= 2.0) return r + (up ? 2.384185791015625e-07 : -2.384185791015625e-07);
  return floatSteps(r, up ? 2 : -2);
#else
  return r;
#endif
}
vec3 logarithm2(vec3 x) { return vec3(logarithm2(x.x), logarithm2(x.y), logarithm2(x.z)); }

// A value the light pass writes into an RGBA16F light buffer, rounded toward
// zero to a 16-bit float (the half-toward-zero variant), so that the
// attachment's own conversion has nothing left to round; the model leaves
// the rounding to the attachment.
#if LIGHTCTS_ADMISSIBLE_VARIANTS
float halfTowardZero(float x) {
  uint bits = floatBitsToUint(x);
  float a = abs(x);
  if (a >= 65504.0) return x < 0.0 ? -65504.0 : 65504.0;
  if (a < 6.103515625e-05) return sign(x) * floor(a * 16777216.0) / 16777216.0;  // half subnormals: steps of 2^-24
  return uintBitsToFloat(bits & ~0x1fffu);  // keep 10 mantissa bits, drop the rest
}
#endif
vec3 halfTowardZero(vec3 v) {
#if LIGHTCTS_ADMISSIBLE_VARIANTS
  if (ADMISSIBLE == ADMISSIBLE_HALF_TOWARD_ZERO)
    return vec3(halfTowardZero(v.x), halfTowardZero(v.y), halfTowardZero(v.z));
#endif
  return v;
}

// A bilinear sample of level 0 at uv (wrapping with `repeat`, else clamped
// to the edge), as a LINEAR filter computes it but with the weights
// truncated to `steps` divisions of a texel (the filter-weights-truncated
// variant: 2^subTexelPrecisionBits, the grid Vulkan lets weights snap to);
// otherwise the driver's own textureLod.
vec4 filteredTexel(sampler2D image, vec2 uv, bool repeat, float steps) {
#if !LIGHTCTS_ADMISSIBLE_VARIANTS
  return textureLod(image, uv, 0.0);
#else
  if (ADMISSIBLE != ADMISSIBLE_FILTER_WEIGHTS_TRUNCATED) return textureLod(image, uv, 0.0);
  ivec2 size = textureSize(image, 0);
  vec2 x = uv * vec2(size) - 0.5;
  vec2 base = floor(x);
  vec2 weight = floor((x - base) * steps) / steps;
  ivec2 i0 = ivec2(base), i1 = i0 + 1;
  if (repeat) {
    i0 = ((i0 % size) + size) % size;
    i1 = ((i1 % size) + size) % size;
  } else {
    i0 = clamp(i0, ivec2(0), size - 1);
    i1 = clamp(i1, ivec2(0), size - 1);
  }
  vec4 t00 = texelFetch(image, ivec2(i0.x, i0.y), 0), t10 = texelFetch(image, ivec2(i1.x, i0.y), 0);
  vec4 t01 = texelFetch(image, ivec2(i0.x, i1.y), 0), t11 = texelFetch(image, ivec2(i1.x, i1.y), 0);
  return mix(mix(t00, t10, weight.x), mix(t01, t11, weight.x), weight.y);
#endif
}

// The snapping variants: the clip position `clip` with its framebuffer x and
// y moved to the device's sub-pixel grid, down, up, or each axis by a hash
// of the grid cell it lies in (so each vertex its own way). `grid`: x, y the framebuffer's size in pixels, z the grid's
// steps per pixel (2^subPixelPrecisionBits), w the framebuffer's y direction
// against NDC y (+1 OpenGL, -1 Vulkan's flipped viewport), so that "down"
// is down in the rasteriser's own coordinates. A vertex behind the camera,
// or of an object that has one (`snappable` false), stays: a device snaps
// the clipped polygon's vertices, which a vertex stage never sees, and
// moving the unclipped ones would move the clipped ones without bound.
vec4 snappedClipPosition(vec4 clip, vec4 grid, bool snappable) {
#if !LIGHTCTS_ADMISSIBLE_VARIANTS
  return clip;
#else
  bool down = ADMISSIBLE == ADMISSIBLE_SNAP_DOWN, up = ADMISSIBLE == ADMISSIBLE_SNAP_UP;
  bool hashed = ADMISSIBLE == ADMISSIBLE_SNAP_PER_VERTEX;
  if (!(down || up || hashed) || !snappable || clip.w <= 0.0) return clip;
  vec2 ndc = clip.xy / clip.w;
  vec2 framebuffer = vec2(ndc.x + 1.0, grid.w * ndc.y + 1.0) * 0.5 * grid.xy;
  vec2 steps = framebuffer * grid.z;
  vec2 snapped = ceil(steps);
  if (down) snapped = floor(steps);
  if (hashed) {
    // Each axis's direction from a hash of its grid cell, not of the vertex:
    // two vertices in one cell (an unwelded seam's, 0.0002 px apart) round
    // the same way, as any rounding of a coordinate does, and a crack opens
    // only where a grid line runs between them.
    uvec2 cell = uvec2(ivec2(floor(steps)));
    uvec2 hash = cell * uvec2(0x9e3779b1u, 0x85ebca77u);
    hash ^= hash >> 15;
    hash *= uvec2(0xc2b2ae3du, 0x27d4eb2fu);
    hash ^= hash >> 13;
    snapped = vec2((hash.x & 1u) != 0u ? ceil(steps.x) : floor(steps.x), (hash.y & 1u) != 0u ? ceil(steps.y) : floor(steps.y));
  }
  vec2 moved = snapped / grid.z / grid.xy * 2.0 - 1.0;
  return vec4(moved.x * clip.w, grid.w * moved.y * clip.w, clip.zw);
#endif
}

// The light loops' order (the lights-reversed variant): the index of the
// i-th light of `count` summed.
int summationIndex(int i, int count) {
#if LIGHTCTS_ADMISSIBLE_VARIANTS
  if (ADMISSIBLE == ADMISSIBLE_LIGHTS_REVERSED) return count - 1 - i;
#endif
  return i;
}

#endif
