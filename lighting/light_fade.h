// Fading the last kept lights: the popping mitigation of docs/model.md, an
// extension of SPEC 5.1 that a scene opts into with pipeline.fade_last_lights.
//
// A plain cut at the budget switches a light's whole contribution on or off
// the moment it passes the first dropped light in distance. With fading, the
// weight of a kept point/spot light is a function of its squared distance to
// the camera and of two squared distances of the frame's order:
//
//   cut   = d2 of the first dropped point/spot light (the 65th in srp)
//   start = d2 of the kept light just before the last N kept ones, or 0 (the
//           camera itself) when fewer than N + 1 are kept
//
//   weight = 0                              when d2 >= cut
//          = 1                              when d2 <= start
//          = (cut - d2) / (cut - start)     otherwise
//
// The k-th smallest of continuous functions is continuous, so cut and start
// move continuously with the camera, and so does the weight, also while two
// lights swap ranks; a light crossing the cut has d2 == cut there, weight 0 on
// both sides. A weight that depended on the rank alone would jump whenever
// ranks swap. Without a dropped light nothing fades (weight 1).
#pragma once

#include <optional>
#include <vector>

namespace lighting {

// The weight of one light at squared distance d2 (see above). The test for
// d2 >= cut comes first, so equal start and cut never divide by zero, and a
// kept light tied with the first dropped one gets the dropped one's 0.
double fadeWeight(double d2, double start, double cut);

// The weights of the kept point/spot lights, given their squared distances in
// kept order (ascending), the squared distance of the first dropped one
// (nullopt: none is dropped) and N = fade_last_lights (0: all weights 1).
std::vector<double> fadeWeights(const std::vector<double>& keptDistanceSquared,
                                std::optional<double> firstDroppedDistanceSquared, int fadeCount);

}  // namespace lighting
