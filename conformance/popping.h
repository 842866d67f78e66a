// SPEC 6's popping score: for an animated scene, the largest frame-to-frame
// jump of a backend's error against the `--ideal` reference,
// max over pixels |e_f - e_(f-1)| with e = backend - ideal.
#pragma once

#include "imaging/image.h"
#include "reference/reference_renderer.h"

namespace conformance {

// e = result - ideal per RGB channel where the ideal reference compares the
// pixel (mask != 0), NaN elsewhere so that poppingJump skips it.
// `maxError` receives max |e| over the finite entries.
imaging::Image idealError(const imaging::Image& result, const reference::ReferenceImages& ideal, double& maxError);

// max |current - previous| over entries finite in both (0 when none).
double poppingJump(const imaging::Image& previous, const imaging::Image& current);

}  // namespace conformance
