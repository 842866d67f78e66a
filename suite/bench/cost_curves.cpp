// The cost curves: frame time against the light count (forward against
// deferred), the resolution and the object count. Speed only: no error
// counters (an ideal reference per point would cost more than the whole curve).
#include "baking/bake.h"
#include "suite/bench/bench_families.h"
#include "suite/bench/bench_scenes.h"

#include <optional>
#include <utility>
#include <vector>

namespace bench {
namespace {

// A curve point of the synthetic field, made when a benchmark the filter
// keeps first needs it; `clusters` for the clustered mode.
LazyFrame curveFrame(const FieldSpec& field, const std::string& name,
                     std::optional<lighting::ClusterGridSpec> clusters = std::nullopt) {
  return lazyBenchFrame(false, [field, name, clusters] {
    BenchFrameSpec spec;
    spec.prepared = baking::prepareBakedScene(fieldScene(field, name));
    spec.everyLightInView = true;
    spec.clusters = clusters;
    return makeBenchFrame(std::move(spec));
  });
}

std::string sizeName(int width, int height) { return std::to_string(width) + "x" + std::to_string(height); }

}  // namespace

void registerCurves(Registrar& r) {
  const RunState& run = r.run();
  const bool quick = run.settings.quick;
  // A slow driver's full set has no curves (its share of the full
  // bench's 10 minutes): how a reference rasterizer's time grows
  // with lights, objects and pixels tells a reader nothing about a renderer,
  // and its field modes keep its errors. Its --quick run still draws each.
  if (run.slow() && !quick) return;
  // The light and object curves at 640x360 (a quarter of the field's
  // pixels, to fit the time budget), at 256x144 with --quick (a smoke run:
  // that every curve draws, not what it costs) and at 128x72 with --quick
  // on a slow driver, whose frames are slow even at 256x144.
  const bool tiny = run.slow();  // and so --quick
  const bool small = quick && !tiny;
  const int curveWidth = tiny ? 128 : small ? 256 : 640, curveHeight = tiny ? 72 : small ? 144 : 360;

  const std::vector<int> lightCounts =
      quick ? std::vector<int>{1, 64, 256} : std::vector<int>{1, 2, 4, 8, 16, 32, 64, 128, 256};
  // Deferred against forward along the light count: where the volumes
  // (a few per pixel) overtake every kept light per pixel.
  // With --quick the deferred curve in hdr32 alone: the other buffers draw
  // the same volumes.
  // The clustered mode beside them: the light count a pixel's
  // cluster holds grows with the lights' overlap, not with the count kept.
  // The all-lights points are what the reports' two-term limit is fitted to
  // (a fixed cost per pixel plus one per pixel-light, docs/performance.md).
  std::vector<FrameMode> lightModes = {FrameMode::AllLights, FrameMode::Clustered};
  if (!quick) lightModes.push_back(FrameMode::PerObject);
  lightModes.push_back(FrameMode::DeferredHdr32);
  if (!quick) lightModes.insert(lightModes.end(), {FrameMode::DeferredHdr16, FrameMode::DeferredLdr8});
  for (const FrameMode mode : lightModes) {
    for (const int n : lightCounts) {
      FieldSpec spec;
      spec.width = curveWidth;
      spec.height = curveHeight;
      spec.mode = mode;
      lightGridFor(n, spec.lightColumns, spec.lightRows);
      const std::string x = std::to_string(n);
      const auto clusters = mode == FrameMode::Clustered ? std::optional(run.settings.clusterGrid) : std::nullopt;
      r.frame("curve-lights", modeName(mode), x,
              curveFrame(spec, std::string("curve-lights-").append(x + "-" + modeName(mode)), clusters), false);
    }
  }

  // The clustered mode against its tile size, the 64 lights of
  // the field at the curves' size and the slices of --cluster_slices: small
  // tiles list fewer lights per pixel but cost more headers and binning.
  const std::vector<int> tileSizes = quick ? std::vector<int>{8, 64} : std::vector<int>{4, 8, 16, 32, 64};
  for (const int tile : tileSizes) {
    FieldSpec spec;
    spec.width = curveWidth;
    spec.height = curveHeight;
    spec.mode = FrameMode::Clustered;
    lighting::ClusterGridSpec grid = run.settings.clusterGrid;
    grid.tileSize = tile;
    const std::string x = std::to_string(tile);
    r.frame("curve-cluster-tile", modeName(FrameMode::Clustered), x, curveFrame(spec, "curve-cluster-tile-" + x, grid),
            false);
  }

  std::vector<std::pair<int, int>> sizes;
  if (tiny) sizes = {{64, 36}, {128, 72}};
  else if (small) sizes = {{128, 72}, {256, 144}};
  else sizes = {{256, 256}, {640, 360}, {1280, 720}, {1920, 1080}};
  for (const auto& [w, h] : sizes) {
    FieldSpec spec;
    spec.width = w;
    spec.height = h;
    const std::string x = sizeName(w, h);
    r.frame("curve-resolution", modeName(FrameMode::AllLights), x, curveFrame(spec, "curve-resolution-" + x), false);
  }

  const std::vector<int> sides = quick ? std::vector<int>{1, 8} : std::vector<int>{1, 2, 4, 8, 16};
  for (const int side : sides) {
    FieldSpec spec;
    spec.width = curveWidth;
    spec.height = curveHeight;
    spec.tileColumns = spec.tileRows = side;
    spec.boxes = false;
    const std::string x = std::to_string(side * side);
    r.frame("curve-objects", modeName(FrameMode::AllLights), x, curveFrame(spec, "curve-objects-" + x), false);
  }
}

}  // namespace bench
