// The tolerance model (SPEC 7): its named constants, and pixelTolerance, the
// formula that combines them into a pixel's tolerance. docs/tolerances.md
// derives each one; a constant or the formula changes only together with
// that document.
//
// A pixel's tolerance is the largest difference a correct float32
// implementation of SPEC 3 may show against the double-precision value V:
//
//   tolerance = albedo * arithmetic bound of the light sum
//               + albedo * filtering bound of the lightmap
//               + largest change over sub-pixel shifts
//               + albedo * interpolation allowance (against real time)
//               + storage rounding of V
//               + flush-to-zero floor
//
// (SPEC 3.8's srp materials: the diffuse colour for the albedo, plus F0 times
// the bound of the specular lobes, specular_bound.h.) A scene's
// `tolerance_scale` is not part of it: the comparison applies it
// (comparison/image_comparison.cpp), once.
//
// The bounds of the terms come from the reference (light_evaluation.cpp,
// lightmap_sampling.cpp, deferred_buffers.cpp, baked_lights_realtime.cpp);
// reference_renderer.cpp shades and shifts, and pixelTolerance sums.
#pragma once

#include <glm/common.hpp>
#include <glm/vec3.hpp>

namespace reference::tolerance {

// float32 unit roundoff: a value rounded to nearest is off by at most u
// relative, as the CPU rounds what it uploads.
constexpr double kUnitRoundoff = 0x1p-24;

// One GPU operation's rounding, the unit of the step counts below: x + y,
// x * y and conversions are "correctly rounded" in an implementation-defined
// rounding mode (no shader here declares RoundingModeRTE), so either
// neighbour of the exact result, under 1 ULP: 2^-23 relative. (A count of
// ULPs, such as the divide's 2.5, is 2 steps per ULP: at most twice that.)
// The light terms are bounded without counts (reference/float_bound.h).
constexpr double kStepRoundoff = 0x1p-23;

// Position error of a camera-relative implementation, in units of u times the
// magnitudes involved (|p - camera|, |object centre - camera| + radius for the
// model transform, |light - camera| for the light's uploaded position):
// transform (3 products + 3 sums) + interpolation (3 ops), rounded up.
constexpr double kPositionRoundingSteps = 8;

// Vertices snap to the sub-pixel grid. Vulkan: "x_f and y_f have limited
// precision, where the number of fractional bits retained is specified by
// subPixelPrecisionBits" (at least 4; OpenGL's GL_SUBPIXEL_BITS, at least 4
// too). Neither API says how a vertex is rounded to that grid, so each
// vertex's x_f and y_f may be off by up to one whole grid step, each vertex
// on its own: vertexSnapPx(b) = 2^-b pixel, b the device's bits (fewer than
// the minimum count as the minimum).
constexpr int kMinimumSubPixelBits = 4;
inline double vertexSnapPx(int subPixelBits) {
  return 1.0 / double(1 << (subPixelBits < kMinimumSubPixelBits ? kMinimumSubPixelBits : subPixelBits));
}
// What a pixel centre then sees: the snapped triangle's attributes at the
// centre are the unsnapped triangle's at the point its affine map takes
// there, the centre moved by a convex combination of the vertices' moves,
// so anywhere in the square of half-side vertexSnapPx around it (not a rigid
// shift of the image: the move differs across the triangle). To first order
// the value changes by |d/dx| s + |d/dy| s there, which the reference takes
// as the larger change of the two shifts along x plus the larger of the two
// along y (reference_renderer.cpp).

// Pixel centres closer than this to a change of surface (silhouette, object or
// box-face boundary) may go to either side under the snapping above plus the
// tie-breaking rule: masked as don't care. An edge moves by at most sqrt(2)
// vertexSnapPx (the larger move of its two ends), and the ring of eight
// probes at radius r finds every edge nearer than r cos(pi/8): 2 vertexSnapPx
// covers both.
inline double edgeDistancePx(int subPixelBits) { return 2.0 * vertexSnapPx(subPixelBits); }

// Two surfaces closer in depth than this many D32F ULPs of the stored depth
// (plus the position error above) may win the LESS test either way: masked.
// Also applied to the near and far clipping planes.
constexpr double kDepthTieUlps = 8;

// RGBA32F colour attachment: one rounding of the final value.
constexpr double kStorageRoundingSteps = 1;

// Summing n light terms adds up to n roundings of the running sum; the final
// albedo product and ambient add two more.
constexpr double kFinalCombineSteps = 2;

// --- Texture filtering of the lightmap and the shadow mask (SPEC 3.5, 3.6) ---

// SPEC 7: a LINEAR filter's weights are exact to 2^-4 (Vulkan's minimum
// subTexelPrecisionBits = 4), so each weight may be off by up to 2^-4.
constexpr double kFilterWeightPrecision = 0x1p-4;

// One weight error per axis of the bilinear blend: a sample may move by up to
// 2 x 2^-4 of the spread (max - min) of the four texels it blends.
constexpr double kFilterWeightErrorsPerSample = 2;

// The blend itself in float32 (three lerps of 2 operations each), relative to
// the largest texel magnitude; the texels are RGBA32F, so fetching is exact.
constexpr double kFilterBlendRoundingSteps = 6;

// The lightmap UV in float32, absolute (|uv| <= 1 on the plane): the vertex
// stage's x * (1/sx) + 0.5 (float local x, float 1/sx, product, sum: 3u after
// rounding up) plus the interpolator (perspective-correct weights and a sum of
// three products, or a plane equation: 13u, rounded up) = 16u.
constexpr double kLightmapUvRoundingSteps = 16;

// Against real time (expect.against = "realtime"): a correct bake stores each
// texel's double irradiance rounded once to float32 (RGBA32F).
constexpr double kTexelStorageRoundingSteps = 1;

// Adding the sampled lightmap to the light sum: one more rounding of the result.
constexpr double kLightmapAddRoundingSteps = 1;

// mix(1, mask[c], strength) (2 operations) and its product with the light's
// attenuation (1): relative to the light term.
constexpr double kShadowMaskRoundingSteps = 3;

// GPUs may flush denormals to zero (Vulkan allows it for 32-bit floats): any
// value below the smallest normal float may read as 0.
constexpr double kFlushToZeroFloor = 0x1p-126;

// --- The deferred path (SPEC 3.7; docs/tolerances.md "Deferred buffers") ---

// Position reconstruction, depth: the light pass gets the window depth the
// G-buffer stored (gl_FragCoord.z, float32 in RGBA32F, so storing is exact)
// and maps it back through the float32 inverse view-projection. The
// rasteriser's depth is off by the same kDepthTieUlps the depth test allows
// (8 ULPs, absolute units of u since the depth is below 1); the float matrix
// entries of the depth-to-w row (2 roundings) and its product and sum (2)
// add 4: 12 units of u of window depth, turned into view depth by
// |d z_view / d z_window|.
constexpr double kReconstructionDepthSteps = 12;

// Position reconstruction, screen position: ndc.xy = vClip.xy / vClip.w
// interpolated over the light volume's triangle (perspective-correct weights,
// a sum of three products, a divide), absolute in units of u of |ndc| <= 1,
// turned into world units by the view's half-extent at the point's depth.
// Clipped triangle vertices lie within |x|, |y| <= w (a guard band multiplies
// this, but a lateral error is also a sub-pixel shift: 13u of NDC is 1e-4
// pixel at 256 pixels, far inside vertexSnapPx).
constexpr double kReconstructionNdcSteps = 13;

// The float32 inverse view-projection product itself and the divide by w, in
// units of u times |p - camera|: 4 entries rounded, 4 products, 3 sums, the
// divide (12), with the magnitudes of a rotation's row summing to at most
// sqrt(3) |p - camera| and the projection's tangent: 16 after rounding up.
constexpr double kReconstructionMatrixSteps = 16;

// The light pass multiplies each light's term by the albedo before the blend
// adds it (forward multiplies the sum once): one more rounding per light.
constexpr double kDeferredAlbedoProductSteps = 1;

// hdr16 (RGBA16F): a half has 11 significant bits. Each additive blend of a
// light that adds something rounds the incoming value and the new running
// sum to half (docs/tolerances.md), and "the rounding mode is not defined"
// (Floating-Point Format Conversions): either neighbour, under 1 ULP of a
// half, 2^-10 relative (the half-toward-zero admissible variant).
constexpr double kHalfRounding = 0x1p-10;

// A device may flush 16-bit denormals (below 2^-14) to zero on conversion:
// absolute floor of each half rounding.
constexpr double kHalfFlushFloor = 0x1p-14;

// ldr8 (RGBA8 UNORM): a value is stored as n / 255. Vulkan lets the
// conversion return either of the two closest values ("implementations
// should round to nearest" is a recommendation, not a rule), so a
// conformant device may be up to one whole step off per conversion.
constexpr double kUnormSteps = 255.0;
constexpr double kUnormRoundingError = 1.0 / kUnormSteps;

// ldr8's decode -log2(max(x, 1/255)) saturates the light sum here.
constexpr double kLdr8SmallestDecoded = 1.0 / kUnormSteps;

// GLSL exp2 is within 3 + 2|c| ULP (relative 2u each) of exp2(-c).
constexpr double kExp2Ulps = 3;
constexpr double kExp2UlpsPerUnitArgument = 2;

// GLSL log2 of the decode: 3 ULP of results below 8 (log2(255) < 8), or
// 2^-21 absolute for x in [0.5, 2]: at most 3 x 2^-20 absolute.
constexpr double kLdr8DecodeAbsError = 3 * 0x1p-20;

// --- The specular lobe (SPEC 3.8; docs/tolerances.md "Specular lobe") ---

// fl(normalize(v)) against v / |v|, split along and across v
// (specular_bound.h): its length is off by dot(v, v) (3u, all terms
// positive; half of it through the root), inversesqrt (2 ULP = 4u) and the
// product (u): 6.5u, rounded up to 7; its direction only by the product's
// rounding of each component, sqrt(3) u < 2u.
constexpr double kNormalizedLengthSteps = 7;
constexpr double kNormalizedDirectionSteps = 2;

// dot of two vectors of length <= 1 (three products, two sums), absolute.
constexpr double kUnitDotRoundingSteps = 3;

// L + V: one rounding per component of a vector of length <= 2.
constexpr double kVectorAddSteps = 2;

// The interpolated normal before it is normalised: three products and two
// sums of the perspective-correct barycentric blend, relative to |n| <= 1.
constexpr double kNormalInterpolationSteps = 3;

// specularStrength's quotient r2 / (d2 * m * k): two products (u each) and a
// divide (2.5 ULP = 5u), relative.
constexpr double kLobeQuotientSteps = 7;

// srp: diffuse = A * (0.96 * (1 - metallic)): float(A), float(0.96), 1 - m,
// two products, relative to diffuse; plus float(metallic)'s u m, absolute in
// 1 - m (brdf_bound in reference_renderer.cpp).
constexpr double kDiffuseColourSteps = 4;

// srp: F0 = mix(0.04, A, metallic) = 0.04 (1 - m) + A m: float(A),
// float(0.04), 1 - m, two products and a sum, relative to max(A, 0.04).
constexpr double kSpecularColourSteps = 6;

// radiance * specularStrength (1), times F0 and added to diffuse * radiance
// (2): relative to the specular part.
constexpr double kSpecularTermSteps = 3;

// --- Cookies (SPEC 3.10; docs/tolerances.md "Cookies") ---

// The cookie coordinate in float32, as a position error in units of u times
// the distance it is measured over (|p - light| for spot and point, |p -
// camera| for directional): the basis dot products (5 operations), the
// divide by the tile size or q.z tan (2.5 ULP = 5u... rounded into 8 with
// the 0.5 + 0.5 x of the spot).
constexpr double kCookieCoordinateSteps = 8;

// --- Real-time shadow maps (SPEC 3.9; docs/tolerances.md "Shadow maps") ---

// A map texel's stored depth: the shadow pass rasterises D32F depth with the
// same interpolation error the camera's depth test allows (kDepthTieUlps, in
// units of u: depth <= 1), from vertices whose float32 position is off by
// kShadowPositionSteps u times the magnitudes (|vertex - camera| and |light
// origin - camera|): the model transform (kPositionRoundingSteps) and the
// light's clip transform (4 products and 3 sums per row, 8 after rounding up).
constexpr double kShadowPositionSteps = 16;

// Which surface a texel centre sees: the shadow pass snaps vertices to the
// sub-pixel grid like the camera's (vertexSnapPx of a texel, each vertex on
// its own), so the reference also takes the depths its plane has at the
// corners of that square (a plane's depth is linear: its extremes there);
// centres within edgeDistancePx of a change of surface admit either
// surface's depth (or the clear value 1).

// The lookup's map coordinates and reference depth: clip = M p' (the same
// transform error as above, as a position error of p'), then x / w, y / w,
// z / w (2.5 ULP each) and 0.5 + 0.5 x: 4u absolute on coordinates and depth
// of magnitude <= 1, on top of the position error.
constexpr double kShadowCoordinateSteps = 4;

// A bilinear or tent weight is exact to the device's sub-texel precision
// (ReferenceOptions::filterWeightPrecision, SPEC 3.9's 2^-4 minimum); the
// tent's own weights and fetch offsets (a few operations each on o in
// [-0.5, 0.5]) add this many u, relative.
constexpr double kShadowTentWeightSteps = 16;

// shadowAtten = saturate(mix(1, s, strength) + fade) (3 operations) and its
// product with the light's attenuation (1), relative to the light term.
constexpr double kShadowAttenuationSteps = 4;

// SPEC 3.9's cap on ambiguity: a scene in which more than this fraction of
// the compared shadowed pixels have an interval [s_lo, s_hi] wider than
// kAmbiguousShadowWidth is a defective scene.
constexpr double kAmbiguousShadowWidth = 0.01;
constexpr double kMostAmbiguousShadowFraction = 0.05;

// --- The combination ---

// The formula at the top of this file, per channel, for a pixel whose shaded
// value is `value` (V). `shadedBound`: the first two terms, already times the
// albedo, with the roundings of the final combine and of the light buffer
// (reference_renderer.cpp, shade()). `shiftChange`: the largest |V(shifted) -
// V| over the sub-pixel shifts. `interpolation`: the albedo times the
// interpolation allowance, the largest over the centre and its shifts; 0
// unless the scene is checked against real time. A pixel that sees no
// surface passes zeros and gets the floor alone.
inline glm::dvec3 pixelTolerance(const glm::dvec3& value, const glm::dvec3& shadedBound,
                                 const glm::dvec3& shiftChange, const glm::dvec3& interpolation) {
  return glm::dvec3(kFlushToZeroFloor) +
         (shadedBound + shiftChange + interpolation + glm::abs(value) * (kStorageRoundingSteps * kStepRoundoff));
}

}  // namespace reference::tolerance
