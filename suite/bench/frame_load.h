// What one frame asks of the device, measured on the CPU once per benchmark
// frame: pixels, kept lights and per-pixel light evaluations. The draw
// benchmarks report it beside their time (pixels_per_s, lights_per_pixel,
// the physical limit of docs/performance.md).
#pragma once

#include "lighting/frame.h"

namespace bench {

struct FrameLoad {
  double pixels = 0;
  // Per-pixel light evaluations, averaged over the image: each object's
  // per-pixel light count (Frame::lightsForObject: every kept light without
  // lists, kept directional + min(count, lighting::kMaxLightsPerObject) with
  // srp lists, the legacy profile's per-pixel list positions) weighted by the
  // pixels it covers, found by one primary ray per sample on a grid of at
  // most 256x256 samples (the reference's BVH); background pixels count 0.
  // Overdraw (a pixel shaded twice before the depth test hides it) and vertex
  // lights are not counted. Deferred (SPEC 3.7): the light volumes that shade
  // the pixel (DeferredCoverage), not the lights of its object. Clustered:
  // the directional lights and the lights of the pixel's cluster.
  double lightsPerPixel = 0;
  int keptLights = 0;
  // Every triangle the frame draws (each object's mesh once): what a mesh
  // field costs in vertex work beside the synthetic one.
  double triangles = 0;
};

FrameLoad loadOf(const lighting::Frame& frame);

}  // namespace bench
