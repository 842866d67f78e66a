// The synthetic scenes of the CPU preparation benchmarks
// (docs/performance.md): built in code, deterministic (a fixed-seed generator),
// so every run times the same work.
#pragma once

#include "lighting/scene.h"

namespace bench {

// `curve-lights`: `lights` point and spot lights (half each) over a square
// field whose area grows with the count (one light per 4 square units), ranges
// 1..3, 16 boxes in the middle of the field, an orthographic camera above that
// sees the whole field: every light is visible, the worst case of SPEC 5.1's
// sort. `perObject` switches per-object lists on (SPEC 5.2).
lighting::Scene curveLightsScene(int lights, bool perObject);

// `curve-objects`: `objects` boxes (0.5) scattered over a 40 x 40 field under
// an 8 x 8 grid of 64 point lights (range 4), per-object lists on; every light
// is visible and kept, each object touches a few of them.
lighting::Scene curveObjectsScene(int objects);

// `curve-lights/shadow-mask`: one mixed directional light with shadows and
// `lights` - 1 mixed point/spot lights with shadows over a field of constant
// density (one light per 4 square units, ranges 0.5..2): each overlaps a few
// neighbours, so channels are reused far apart and some lights are demoted
// (SPEC 5.3).
lighting::Scene shadowMaskScene(int lights);

// `lights64-1280x720`: the frame benchmarks' field (bench_scenes.h), 64 point
// lights over an 8 x 8 field of tiles and 16 boxes, 1280 x 720.
lighting::Scene sixtyFourLightsScene(bool perObject);

}  // namespace bench
