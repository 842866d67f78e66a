// The double-precision reference (SPEC 6): one ray through every pixel centre
// against the same triangles the backends draw, the model of SPEC 3 and 4
// evaluated exactly at the nearest front-facing hit, a per-pixel tolerance
// (tolerance_model.h) and a mask of don't-care pixels.
#pragma once

#include "imaging/image.h"
#include "lighting/frame.h"
#include "reference/bvh.h"
#include "reference/tolerance_model.h"
#include "reference/world_triangles.h"

#include <cstdint>
#include <memory>
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
};

// Built once per scene (world triangles and BVH), then renders any frame of it.
class ReferenceRenderer {
 public:
  explicit ReferenceRenderer(std::shared_ptr<const lighting::PreparedScene> prepared);
  ReferenceImages render(const lighting::Frame& frame, const ReferenceOptions& options = {}) const;
  std::size_t triangleCount() const { return world_.triangles.size(); }

 private:
  std::shared_ptr<const lighting::PreparedScene> prepared_;
  WorldTriangles world_;
  Bvh bvh_;
};

}  // namespace reference
