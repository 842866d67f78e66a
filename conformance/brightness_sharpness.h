// How small an error in the lights' brightness a frame's comparison catches:
// the suite's sharpness (SPEC 7; docs/tolerances.md "Sharpness"). A scale
// mutant, made from the rendered image without rendering again: the part of
// each pixel the lights add (the reference's ReferenceImages::lightPart) is
// added to the result times e (lights 1 + e as bright) or -e (1 - e), the
// comparison itself judges the image, and e is bisected to the smallest that
// fails. A pixel's value is linear in e, so it passes for an interval of e
// around 0 and the failing pixels only grow with |e|: the bisection is sound.
// Scaling the lights rather than the whole image keeps pixels that no light
// reaches (ambient and lightmap alone, held to a few roundings) from making
// every scene look sharp.
#pragma once

#include "imaging/image.h"
#include "lighting/scene.h"
#include "reference/reference_renderer.h"

namespace conformance {

struct CaughtScale {
  // The smallest relative error of the lights each way that fails the
  // comparison, within kSharpnessPrecision; +infinity where even lights
  // twice as bright (or none) pass, and 0 where the unscaled image fails already.
  double brighter = 0;
  double darker = 0;
};

// Bisection stops within this much of the threshold, relative.
constexpr double kSharpnessPrecision = 1e-4;

// `lightPart`: what the lights add to each pixel of `reference` (RGB).
CaughtScale smallestCaughtScale(const imaging::Image& result, const imaging::Image& lightPart,
                                const reference::ReferenceImages& reference, const lighting::Expectation& expect);

}  // namespace conformance
