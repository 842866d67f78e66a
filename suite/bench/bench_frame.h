// A benchmark frame: frame 0 of a prepared scene with its load and how it is
// drawn and judged, made once when the benchmark is registered (or on its
// first run) and kept for the whole process. makeBenchFrame is the one
// factory every family (the 64-light field, the lightmap modes, the cost
// curves, the suite scenes) and the time-source calibration make frames with.
#pragma once

#include "lighting/frame.h"
#include "lighting/light_clusters.h"
#include "suite/bench/frame_load.h"

#include <memory>
#include <optional>
#include <string>

namespace bench {

// The lightmap modes: the median time of fresh bakes (no cache) and how many
// bakes it is the median of.
struct BakeTime {
  double medianMs = 0;
  int runs = 0;
};

// What a benchmark frame is made of.
struct BenchFrameSpec {
  std::shared_ptr<const lighting::PreparedScene> prepared;  // frame 0 of it is drawn
  bool fullShader = false;   // draw with ShaderVariant::specialised = false
  std::string referenceKey;  // the cached ideal reference it is compared with; empty: no error counters
  std::string errorKey;      // the cached error (frame and frame_readback share it)
  // The scene whose ideal reference is the error's baseline when it is not
  // `prepared` (the lightmap modes: the same lights in real time; the
  // deferred modes: the forward field); null: `prepared`'s own.
  std::shared_ptr<const lighting::PreparedScene> referencePrepared;
  std::optional<BakeTime> bake;
  // A synthetic scene with every light in view: the cut of SPEC 5.1 must keep
  // min(lights, budget) point/spot lights, or a warning goes to stderr.
  bool everyLightInView = false;
  // The clustered mode (FrameMode::Clustered): frame 0 binned with this grid
  // (lighting::useLightClusters) before its load is measured.
  std::optional<lighting::ClusterGridSpec> clusters;
  // The dense field: every object's list must hold at least this many lights
  // (per-object mode only), or a warning goes to stderr.
  int leastObjectLights = 0;
};

struct BenchFrame {
  BenchFrameSpec spec;
  lighting::Frame frame;
  FrameLoad load;
};

// Prepares frame 0 of spec.prepared and measures its load.
std::shared_ptr<const BenchFrame> makeBenchFrame(BenchFrameSpec spec);

}  // namespace bench
