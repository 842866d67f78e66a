// The arithmetic of the lighting model per pixel and light, and the
// machine's measured peak rate: the two halves of the physical-limit
// estimate (docs/performance.md).
#pragma once

namespace bench {

// Floating-point operations of one point/spot light evaluation in the
// fragment stage (SPEC 3.2 as written in shaders/lighting.glsl), counted
// per operation as docs/performance.md derives.
double flopsPerPixelLight();
// What SPEC 3.8's lobe adds to it per light on an srp material (46).
double flopsOfSpecularLobe();

// Measures the machine's single-precision FMA rate over every core (GFLOP/s),
// with a calibrated kernel: the median of `repetitions` timed runs.
double measurePeakGflops(int repetitions = 5);

}  // namespace bench
