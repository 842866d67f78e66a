// The double-precision reference (SPEC 6): one ray through every pixel centre
// against the same triangles the backends draw, the model of SPEC 3 and 4
// evaluated exactly at the nearest front-facing hit, a per-pixel tolerance
// (tolerance_model.h) and a mask of don't-care pixels.
#pragma once

#include "imaging/image.h"
#include "lighting/frame.h"
#include "reference/bvh.h"
#include "reference/shadow_maps.h"
#include "reference/tolerance_model.h"
#include "reference/world_triangles.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include <glm/vec3.hpp>

namespace reference {

struct ReferenceOptions {
  bool ideal = false;  // SPEC 6 `--ideal`: every non-baked light per pixel, no budgets
  // `"expect": {"against": "realtime"}` (docs/model.md): on lightmapped
  // objects the baked lights are evaluated per pixel in real time instead of
  // read from the lightmap, with an interpolation allowance in the tolerance
  // (baked_lights_realtime.h). Combines with `ideal`.
  bool bakedLightsRealtime = false;
  int threads = 0;     // 0: every hardware thread
  // Also return every pixel's double value (ReferenceImages::exactValue), for
  // tests that check the model to more digits than the float image holds.
  bool keepExactValues = false;
  // Also return the tolerance's two parts (ReferenceImages::toleranceArithmetic,
  // toleranceShift), to see which dominates where (docs/tolerances.md).
  bool keepToleranceTerms = false;
  // SPEC 7: a LINEAR filter's weights are exact to this (2^-bits of the
  // device's sub-texel precision; 2^-4, the Vulkan minimum, when unknown):
  // the filtering term of the lightmaps, shadow masks and cookies.
  double filterWeightPrecision = tolerance::kFilterWeightPrecision;
  // The device's sub-pixel bits (subPixelPrecisionBits; the minimum 4 when
  // unknown): how far a vertex may snap, for the sub-pixel term, the edge
  // mask and the shadow maps' texels (tolerance::vertexSnapPx).
  int subPixelPrecisionBits = tolerance::kMinimumSubPixelBits;
  // Also return ReferenceImages::shadowInterval (SPEC 3.9 evidence).
  bool keepShadowIntervals = false;
  // The value and its mask only, no tolerance (left 0): the benchmarks'
  // error baseline (suite/bench/run_state.h). The sub-pixel shifts are still
  // traced, since they decide the mask, but not shaded (eight of a pixel's
  // nine shadings), and the one shading evaluates its light sums without
  // their float32 bounds and gathers no shadow statistics (shadowedPixels,
  // ambiguousShadowPixels and shadowInterval stay empty), so an ideal
  // 1280x720 frame costs a fraction of a full one. Value and mask are bit
  // for bit those of a full render.
  bool valueOnly = false;
  // Also return ReferenceImages::lightPart (the suite's sharpness).
  bool keepLightPart = false;
};

struct ReferenceImages {
  imaging::Image value;      // RGBA: RGB value, A mask (1 compared, 0 don't care)
  imaging::Image tolerance;  // RGB
  std::int64_t lightEvaluations = 0;  // pixel-light evaluations, tolerance shading included
  std::int64_t maskedPixels = 0;
  // keepExactValues only: row-major, row 0 at the top, the double colour of
  // each pixel before any rounding (background 0); empty otherwise.
  std::vector<glm::dvec3> exactValue;
  // keepToleranceTerms only (RGB, else empty): the sub-pixel-shift term
  // (section 2 of docs/tolerances.md) and everything else, the arithmetic,
  // filtering, buffer and storage bounds; they sum to `tolerance`.
  imaging::Image toleranceArithmetic;
  imaging::Image toleranceShift;
  // keepLightPart only (RGB, else empty): what the lights add to each
  // pixel's value, all of it but A * (ambient + lightmap); 0 on the background.
  imaging::Image lightPart;
  // SPEC 3.9's cap on ambiguity: the compared pixels that some light with a
  // real-time shadow lights, and those among them whose interval [s_lo,
  // s_hi] is wider than tolerance::kAmbiguousShadowWidth for some light.
  std::int64_t shadowedPixels = 0;
  std::int64_t ambiguousShadowPixels = 0;
  // True when ambiguousShadowPixels exceeds tolerance::kMostAmbiguousShadowFraction
  // of shadowedPixels: a defective scene (its comparison fails and says so).
  bool shadowAmbiguityExceedsCap() const;
  // keepShadowIntervals only (else empty): per pixel, the interval [s_lo,
  // s_hi] of admissible shadow-map lookups of the light whose interval is
  // widest there (channels 0, 1), and 1 where a light with a real-time
  // shadow lights the pixel (channel 2); all 1, 1, 0 elsewhere.
  imaging::Image shadowInterval;
};

// Whether ReferenceOptions::filterWeightPrecision can change `prepared`'s
// references: only a filtered texture reads it (lightmaps and shadow masks,
// cookies, shadow maps). For any other scene every device's sub-texel
// precision gives the same reference, so one is rendered for all
// (conformance::SceneReferences, the reference cache).
bool readsFilteredTextures(const lighting::PreparedScene& prepared);

// What a pixel centre sees, as render() finds it: the nearest front-facing
// hit between the near and far planes, its point, the interpolated unit
// normal and the object.
struct VisibleSurface {
  lighting::Vec3 point{0.0};
  lighting::Vec3 normal{0.0, 1.0, 0.0};
  int object = -1;
};

// Built once per scene (world triangles and BVH), then renders any frame of it.
class ReferenceRenderer {
 public:
  explicit ReferenceRenderer(std::shared_ptr<const lighting::PreparedScene> prepared);
  ReferenceImages render(const lighting::Frame& frame, const ReferenceOptions& options = {}) const;
  // The surface at pixel (x, y)'s centre; nullopt for the background.
  std::optional<VisibleSurface> visibleSurface(const lighting::Frame& frame, int x, int y) const;
  std::size_t triangleCount() const { return world_.triangles.size(); }
  // SPEC 3.9: the reference's shadow maps of `frame`, one per scene light
  // with a shadow map (null for the others), as render() builds them for a
  // device with `subPixelBits` (ReferenceOptions::subPixelPrecisionBits).
  std::vector<std::unique_ptr<ReferenceShadowMap>> shadowMaps(
      const lighting::Frame& frame, int threads = 0, int subPixelBits = tolerance::kMinimumSubPixelBits) const;

 private:
  std::shared_ptr<const lighting::PreparedScene> prepared_;
  WorldTriangles world_;
  Bvh bvh_;
};

}  // namespace reference
