// Comparing a backend image with the reference, pixel by pixel (SPEC 7).
// Pure computation: no files, no printing (comparison_report.h does those).
#pragma once

#include "comparison/verdict.h"  // Verdict: a comparison yields Pass, Fail or QualityWarning
#include "imaging/image.h"
#include "lighting/scene.h"
#include "reference/reference_renderer.h"

#include <vector>

namespace comparison {

// One failing pixel, with everything needed to see why it failed.
struct PixelReport {
  int x = 0;
  int y = 0;
  float result[3] = {};
  float reference[3] = {};
  float tolerance[3] = {};  // as in reference.tolerance; the allowed |difference| is this * toleranceScale
  double excess = 0;        // max over RGB of |difference| - allowed; +inf when non-finite
  bool nonFinite = false;   // NaN or infinity in any channel of the result
  // SPEC 3.9: where a light with a real-time shadow lights the pixel, the
  // admissible interval [s_lo, s_hi] of its widest lookup (the reference's
  // shadowInterval; absent when the reference kept none).
  bool shadowed = false;
  float shadowLo = 1, shadowHi = 1;
};

struct Comparison {
  int width = 0;
  int height = 0;
  long long comparedPixels = 0;   // mask != 0
  long long maskedPixels = 0;     // mask == 0 (don't care); comparedPixels + maskedPixels = width * height
  // Compared pixels where some channel of the reference is above the
  // flush-to-zero floor: with none, the frame is black and matching it
  // checks nothing (vacuous_comparison.h).
  long long litComparedPixels = 0;
  long long failingPixels = 0;    // non-finite pixels included, masked or not
  long long nonFinitePixels = 0;
  long long maxFailingPixels = 0;  // copied from the Expectation, so the evidence explains the verdict
  double toleranceScale = 1;       // copied from the Expectation, likewise
  // Metrics over the RGB channels of compared pixels whose result is finite;
  // non-finite pixels are counted in nonFinitePixels instead of swamping these.
  double maxAbsError = 0;
  // "Tightness": largest |difference| / allowed (0 / 0 is 0, x / 0 is +inf); > 1 means failing.
  double maxErrorOverTolerance = 0;
  double rmse = 0;
  std::vector<PixelReport> worst;  // largest excess first; ties by row, then column
  bool comparisonPassed = false;   // failingPixels <= maxFailingPixels and nonFinitePixels == 0
  // SPEC 3.9's cap, copied from the reference: the compared pixels a light
  // with a real-time shadow lights, those whose admissible interval is wider
  // than 0.01, and whether they exceed 5% (a defective scene: Fail, whatever
  // the pixels say, since ambiguity must never pass for agreement).
  long long shadowedPixels = 0;
  long long ambiguousShadowPixels = 0;
  bool defectiveScene = false;
  bool expectFail = false;
  // Pass when comparisonPassed != expectFail: an expect_fail scene exists to
  // prove a known mismatch is detected, so it passing the comparison is a Fail.
  // Non-finite pixels are a Fail even there (SPEC 7: they always fail); a NaN
  // is a defect of its own, not the mismatch the scene is meant to show.
  // A Pass whose frame checks nothing (qualityWarning) is QualityWarning.
  Verdict verdict = Verdict::Fail;
  // Why the frame checks nothing (vacuousComparisonReason), or "": set
  // whatever the verdict; it makes a would-be Pass a QualityWarning.
  std::string qualityWarning;
  // RGB: non-finite magenta (1, 0, 1), failing red (1, 0, 0), masked grey
  // (0.25), passing black; in that order of precedence.
  imaging::Image errorMask;
};

// `result` has 3 or 4 channels (a non-finite alpha fails too); `reference.value`
// 4 (RGB, mask) and `reference.tolerance` 3, all of the same size. Throws
// std::invalid_argument when they are not, or when worstCount < 0.
Comparison compareImages(const imaging::Image& result, const reference::ReferenceImages& reference,
                         const lighting::Expectation& expect, int worstCount = 10);

}  // namespace comparison
