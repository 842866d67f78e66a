// SPEC 3.9's real-time shadow maps in double precision: the reference's own
// maps, built by casting a ray through every texel centre against the scene's
// triangles (both faces: every triangle casts), and the lookup of SPEC 3.9
// (receiver offset, hard, bilinear or tent3x3 compare) at a shaded point.
//
// Beside every value the reference keeps what a correct float32
// implementation may return instead (docs/tolerances.md "Shadow maps"):
// each texel holds the interval of depths a correct shadow pass may store
// (a centre near a caster's silhouette admits the depth beyond it; the
// rasteriser's depth and snapping errors), and each lookup the interval
// [s_lo, s_hi] of admissible results, enumerated the way VK-GL-CTS's
// tcuTexCompareVerifier does: every texel (or cube face) the coordinate's
// error can reach, every compare result within the depth error of its
// boundary, every filter weight within the sub-texel precision.
#pragma once

#include "lighting/shadow_projection.h"
#include "imaging/image.h"
#include "reference/bvh.h"
#include "reference/tolerance_model.h"

#include <vector>

namespace reference {

// What a correct shadow pass may store in one texel: `depth` is SPEC 3.9's
// value (the nearest triangle at the centre, or 1), inside [lo, hi].
struct ShadowTexel {
  double depth = 1;
  double lo = 1, hi = 1;
};

// The result of one lookup: SPEC 3.9's s and the admissible interval.
struct ShadowLookup {
  double s = 1;
  double lo = 1, hi = 1;
  double span() const { return hi - lo; }
};

// How far the GPU's receiver point may be from the double p' (world units):
// the caller's position error of p and of the light's position.
// `depthOnlyMove`: a further move of the receiver (the snapping square's on
// the surface) that only the compares' depth sees; a filter's weights follow
// such a move continuously, which the caller's sampled points hold.
struct LookupError {
  double position = 0;
  double depthOnlyMove = 0;
};

class ReferenceShadowMap {
 public:
  // Builds the map of `projection` (every view) from `bvh`'s triangles.
  // `cameraPosition`: the frame's camera, for the float32 position errors of
  // a camera-relative shadow pass. `threads` as ReferenceOptions::threads.
  // `subPixelBits`: the shadow pass's device's sub-pixel bits, how far its
  // vertices may snap (tolerance::vertexSnapPx, in texels).
  ReferenceShadowMap(lighting::ShadowProjection projection, const Bvh& bvh, const Vec3& cameraPosition,
                     int threads = 0, int subPixelBits = tolerance::kMinimumSubPixelBits);

  const lighting::ShadowProjection& projection() const { return projection_; }
  int resolution() const { return resolution_; }
  int viewCount() const { return int(projection_.views.size()); }
  const ShadowTexel& texel(int view, int i, int j) const {
    return texels_[(std::size_t(view) * resolution_ + j) * resolution_ + i];
  }

  // SPEC 3.9's s for a receiver at p with unit normal N, and its interval.
  // `weightPrecision`: a filter weight's precision (SPEC 3.9: 2^-4 or the
  // device's). The camera is the one the map was built for.
  ShadowLookup lookup(const Vec3& p, const Vec3& N, const LookupError& error, double weightPrecision) const;

  // SPEC 3.9's s alone, exactly as written (no interval).
  double value(const Vec3& p, const Vec3& N) const;

  // One view as an image for evidence: RGB = depth, lo, hi, row 0 = texel row 0.
  imaging::Image viewImage(int view) const;

 private:
  void buildView(int view, const Bvh& bvh, int threads, int subPixelBits);
  double depthError(const lighting::ShadowView& view, const Vec3& q) const;

  lighting::ShadowProjection projection_;
  Vec3 camera_;
  int resolution_ = 0;
  std::vector<ShadowTexel> texels_;
};

}  // namespace reference
