// A benchmark frame: frame 0 of a prepared scene with its load and how it is
// drawn and judged, made on first use (LazyBenchFrame) and kept for the whole
// process. makeBenchFrame is the one factory every family (the 64-light
// field, the lightmap modes, the cost curves, the suite scenes) and the
// time-source calibration make frames with.
#pragma once

#include "lighting/frame.h"
#include "lighting/light_clusters.h"
#include "suite/bench/frame_load.h"

#include <functional>
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

// A benchmark frame made on its first use, not when it is registered: a
// process builds the scenes, traces the loads (a BVH each) and bakes the
// lightmaps of the benchmarks its filter keeps, and of no other. One is
// shared by the benchmarks of a frame (frame, frame_readback, pipeline) and
// the error prepass. Used from one thread at a time: Google Benchmark runs
// one benchmark at once, and the prepass makes its frames before its workers start.
class LazyBenchFrame {
 public:
  using Make = std::function<std::shared_ptr<const BenchFrame>()>;
  // `hasError`: whether the frame made will have a referenceKey (error counters).
  LazyBenchFrame(bool hasError, Make make) : hasError_(hasError), make_(std::move(make)) {}

  bool hasError() const { return hasError_; }
  // The frame, made on the first call; when making it throws, every call throws.
  const BenchFrame& get() {
    if (!made_) made_ = make_();
    return *made_;
  }

 private:
  bool hasError_;
  Make make_;
  std::shared_ptr<const BenchFrame> made_;
};
using LazyFrame = std::shared_ptr<LazyBenchFrame>;

inline LazyFrame lazyBenchFrame(bool hasError, LazyBenchFrame::Make make) {
  return std::make_shared<LazyBenchFrame>(hasError, std::move(make));
}

// A value several lazy frames share (a scene their ideal reference is made
// from, the imported meshes of a field), made when the first of them needs it.
template <class T>
class SharedOnDemand {
 public:
  explicit SharedOnDemand(std::function<T()> make) : state_(std::make_shared<State>(State{std::move(make), {}})) {}
  const T& get() const {
    if (!state_->value) state_->value = state_->make();
    return *state_->value;
  }

 private:
  struct State {
    std::function<T()> make;
    std::optional<T> value;
  };
  std::shared_ptr<State> state_;
};

}  // namespace bench
