// The CPU preparation benchmarks (docs/bench-format.md, kind `prepare`):
//
//   prepare/cpu/curve-lights/all-lights/<n>    prepareFrame + packing, n lights (10 .. 100000)
//   prepare/cpu/curve-lights/per-object/<n>    the same with per-object lists (SPEC 5.2)
//   prepare/cpu/curve-objects/per-object/<n>   64 lights, n objects (10 .. 10000)
//   prepare/cpu/curve-lights/shadow-mask/<n>   assignShadowMaskChannels, n mixed shadowed lights
//   prepare/cpu/lights64-1280x720/<mode>       render_bench's synthetic scene
//   prepare/cpu/lights64-1280x720/clustered-binning  lighting::binLights of the field's frame,
//                                              16-pixel tiles, 16 slices
//   prepare/cpu/curve-lights/clustered-binning/<n>   the same on the field with n lights (16 .. 1024), every
//                                              one binned (past SPEC 5.1's 64 kept: what the binning costs
//                                              where a mode would keep them)
//   prepare/cpu/curve-lightmap/bake/<texels>   baking::bakeScene of the shadowed lightmap scene, N x N texels
//                                              (N = 16 .. 512), no cache, every core, wall-clock time
//
// "Preparation" is what a backend does on the CPU for every frame before it
// records commands: lighting::prepareFrame (camera, visible set, order and
// budgets of SPEC 5.1, per-object lists of 5.2, shader features) and the
// std140 packing of lighting/gpu_packing (the frame block and one object
// block per object). The shadow-mask assignment (5.3) runs once per scene at
// bake time (lighting::prepareScene) and is timed on its own. Each curve
// family carries Google Benchmark's complexity fit (`<family>_BigO`,
// `<family>_RMS`), so the JSON says whether the cost is near-linear.
#include "suite/bench/prepare_benchmarks.h"

#include "app/exit_status.h"
#include "baking/bake.h"
#include "lighting/frame.h"
#include "lighting/gpu_packing.h"
#include "lighting/light_clusters.h"
#include "lighting/shadow_mask_channels.h"
#include "results/bench_names.h"
#include "suite/bench/bench_reporters.h"
#include "suite/bench/bench_scenes.h"
#include "suite/bench/fresh_bake.h"
#include "suite/bench/prepare_scenes.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace bench {
namespace {

// prepare/<rest>: the kind the bench pages know the CPU preparation by.
std::string prepareName(const std::string& rest) { return std::string(results::bench::kPrepare) + rest; }

using namespace lighting;

constexpr int kRepetitions = 5;
constexpr double kMinTimeSeconds = 0.1;       // per repetition
constexpr double kQuickMinTimeSeconds = 0.01;

struct Settings {
  bool quick = false;
  // Google Benchmark flags, placed before the caller's (the later wins).
  std::vector<std::string> defaultFlags() const {
    if (quick) return {"--benchmark_min_time=" + std::to_string(kQuickMinTimeSeconds), "--benchmark_repetitions=1"};
    return {"--benchmark_min_time=" + std::to_string(kMinTimeSeconds),
            "--benchmark_repetitions=" + std::to_string(kRepetitions), "--benchmark_display_aggregates_only=true"};
  }
  std::vector<int> lightCounts() const {
    return quick ? std::vector<int>{10, 100, 1000} : std::vector<int>{10, 100, 1000, 10000, 100000};
  }
  std::vector<int> objectCounts() const {
    return quick ? std::vector<int>{10, 100, 1000} : std::vector<int>{10, 100, 1000, 10000};
  }
  // Texel counts N * N of the bake curve.
  std::vector<int> lightmapTexels() const {
    std::vector<int> out;
    for (const int n : kLightmapResolutions)
      if (!quick || n <= 64) out.push_back(n * n);
    return out;
  }
};

// Scenes are built and baked (prepareScene) once per process, outside the
// timing, on the first call of the benchmark that needs them.
std::shared_ptr<const PreparedScene> preparedScene(const std::string& key, const std::function<Scene()>& make) {
  static std::map<std::string, std::shared_ptr<const PreparedScene>> cache;
  auto [it, inserted] = cache.try_emplace(key);
  if (inserted) it->second = prepareScene(make());
  return it->second;
}

// One frame's CPU work: selection, lists, features, then the packed blocks.
void prepareAndPack(const std::shared_ptr<const PreparedScene>& prepared) {
  Frame frame = prepareFrame(prepared, 0);
  GpuFrameBlock frameBlock = packFrameBlock(frame);
  benchmark::DoNotOptimize(frameBlock);
  const int objects = int(frame.scene().objects.size());
  for (int o = 0; o < objects; ++o) {
    GpuObjectBlock objectBlock = packObjectBlock(frame, o);
    benchmark::DoNotOptimize(objectBlock);
  }
  benchmark::ClobberMemory();
}

// Times prepareAndPack; `itemCount` is what the rate counts (lights or
// objects), `itemName` the counter's name.
void timeFrame(benchmark::State& state, const std::shared_ptr<const PreparedScene>& prepared, double itemCount,
               const char* rateName) {
  for (auto _ : state) prepareAndPack(prepared);
  const Frame frame = prepareFrame(prepared, 0);
  state.SetComplexityN(benchmark::IterationCount(itemCount));
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(itemCount));
  state.counters[std::string(results::bench::kLights)] = double(frame.scene().lights.size());
  state.counters["objects"] = double(frame.scene().objects.size());
  state.counters["visible_lights"] = double(frame.selection.visible.size());
  state.counters["kept_lights"] =
      double(frame.selection.packed.directional.size() + frame.selection.packed.other.size());
  state.counters[rateName] = benchmark::Counter(itemCount, benchmark::Counter::kIsIterationInvariantRate);
}

void curveLights(benchmark::State& state, bool perObject) {
  const int n = int(state.range(0));
  const auto prepared = preparedScene("curve-lights/" + std::to_string(n) + (perObject ? "/per-object" : "/all"),
                                      [&] { return curveLightsScene(n, perObject); });
  timeFrame(state, prepared, n, "lights_per_s");
}

void curveObjects(benchmark::State& state) {
  const int n = int(state.range(0));
  const auto prepared = preparedScene("curve-objects/" + std::to_string(n), [&] { return curveObjectsScene(n); });
  timeFrame(state, prepared, n, "objects_per_s");
}

void lights64(benchmark::State& state, bool perObject) {
  const auto prepared = preparedScene(perObject ? "lights64/per-object" : "lights64/all",
                                      [&] { return sixtyFourLightsScene(perObject); });
  timeFrame(state, prepared, double(prepared->scene.lights.size()), "lights_per_s");
}

// lighting::binLights alone, on frame 0 of the 1280x720 field with n point
// lights (FieldSpec's grid, every light in view). Past the 64 SPEC 5.1 keeps,
// the frame's packed list is widened to every light, so the curve shows what
// binning n lights costs.
void clusteredBinning(benchmark::State& state, int n) {
  const auto prepared = preparedScene("binning/" + std::to_string(n), [&] {
    FieldSpec field;
    field.mode = FrameMode::Clustered;
    lightGridFor(n, field.lightColumns, field.lightRows);
    return fieldScene(field, "binning-" + std::to_string(n));
  });
  Frame frame = prepareFrame(prepared, 0);
  std::vector<int>& packed = frame.selection.packed.other;
  packed.clear();
  for (int l = 0; l < int(prepared->scene.lights.size()); ++l) packed.push_back(l);
  frame.selection.packed.otherWeight.assign(packed.size(), 1.0);
  const ClusterGridSpec grid;
  std::size_t listed = 0;
  for (auto _ : state) {
    LightClusters clusters = binLights(frame, grid);
    listed = clusters.lights.size();
    benchmark::DoNotOptimize(clusters);
  }
  const ClusterGrid g = clusterGridFor(frame.view, grid);
  state.SetComplexityN(int(packed.size()));
  state.counters[std::string(results::bench::kLights)] = double(packed.size());
  state.counters["cluster_tile"] = grid.tileSize;
  state.counters["cluster_slices"] = grid.depthSlices;
  state.counters["clusters"] = g.clusterCount();
  state.counters["listed_lights"] = double(listed);
  state.counters["lights_per_s"] = benchmark::Counter(double(packed.size()), benchmark::Counter::kIsIterationInvariantRate);
}

void shadowMask(benchmark::State& state) {
  const int n = int(state.range(0));
  // Only the Scene is needed; the cache holds it inside a PreparedScene.
  const auto prepared = preparedScene("shadow-mask/" + std::to_string(n), [&] { return shadowMaskScene(n); });
  const Scene& scene = prepared->scene;
  for (auto _ : state) {
    ShadowMaskAssignment assignment = assignShadowMaskChannels(scene);
    benchmark::DoNotOptimize(assignment);
  }
  int holders = 0, demoted = 0;
  for (const ShadowMaskEntry& e : prepared->shadowMask.entries) (e.demoted ? demoted : holders) += 1;
  state.SetComplexityN(n);
  state.SetItemsProcessed(std::int64_t(state.iterations()) * n);
  state.counters[std::string(results::bench::kLights)] = n;
  state.counters["channel_holders"] = holders;
  state.counters["demoted"] = demoted;
  state.counters["lights_per_s"] = benchmark::Counter(n, benchmark::Counter::kIsIterationInvariantRate);
}

// The lightmapper on render_bench's lightmap scene (suite/bench/bench_scenes.h):
// one plane of N x N texels under five baked point lights, one with a shadow
// ray per texel (the `lightmap-shadow` scene of the frame benchmarks). A fresh bake every iteration (no cache), parallel over rows
// on every core, so the time is wall-clock (UseRealTime).
void curveLightmapBake(benchmark::State& state) {
  const int texels = int(state.range(0));
  const int n = int(std::lround(std::sqrt(double(texels))));
  const auto prepared = preparedScene("lightmap/" + std::to_string(n), [&] {
    LightmapSpec spec;
    spec.resolution = n;
    spec.shadows = true;  // a shadow ray per texel for one light, as in lightmap-shadow-1280x720
    return lightmapScene(spec, "lightmap-shadow-1280x720");
  });
  for (auto _ : state) {
    auto baked = baking::bakeScene(*prepared, freshBake());
    benchmark::DoNotOptimize(baked);
  }
  state.SetComplexityN(texels);
  state.SetItemsProcessed(std::int64_t(state.iterations()) * texels);
  state.counters[std::string(results::bench::kLightmapTexels)] = texels;
  state.counters[std::string(results::bench::kLights)] = double(prepared->scene.lights.size());
  state.counters["texels_per_s"] = benchmark::Counter(texels, benchmark::Counter::kIsIterationInvariantRate);
}

// Repetitions and the minimum time come from flags (runPrepareBenchmarks puts
// the defaults in front of the caller's arguments): set per benchmark, Google
// Benchmark would append them to every name ("/min_time:0.100/repeats:5").
benchmark::internal::Benchmark* common(benchmark::internal::Benchmark* b) {
  return b->Unit(benchmark::kMicrosecond);
}

benchmark::internal::Benchmark* curve(benchmark::internal::Benchmark* b, const std::vector<int>& points) {
  for (int x : points) b->Arg(x);
  return common(b)->Complexity(benchmark::oAuto);
}

void registerAll(const Settings& settings) {
  for (const bool perObject : {false, true}) {
    const std::string mode = perObject ? "per-object" : "all-lights";
    curve(benchmark::RegisterBenchmark(prepareName("/cpu/curve-lights/" + mode).c_str(),
                                       [perObject](benchmark::State& s) { curveLights(s, perObject); }),
          settings.lightCounts());
  }
  curve(benchmark::RegisterBenchmark(prepareName("/cpu/curve-objects/per-object").c_str(), curveObjects), settings.objectCounts());
  curve(benchmark::RegisterBenchmark(prepareName("/cpu/curve-lights/shadow-mask").c_str(), shadowMask), settings.lightCounts());
  curve(benchmark::RegisterBenchmark(prepareName("/cpu/curve-lightmap/bake").c_str(), curveLightmapBake), settings.lightmapTexels())
      ->UseRealTime();
  for (const bool perObject : {false, true}) {
    const std::string mode = perObject ? "per-object" : "all-lights";
    common(benchmark::RegisterBenchmark(prepareName("/cpu/lights64-1280x720/" + mode).c_str(),
                                        [perObject](benchmark::State& s) { lights64(s, perObject); }));
  }
  common(benchmark::RegisterBenchmark(prepareName("/cpu/lights64-1280x720/clustered-binning").c_str(),
                                      [](benchmark::State& s) { clusteredBinning(s, 64); }));
  curve(benchmark::RegisterBenchmark(prepareName("/cpu/curve-lights/clustered-binning").c_str(),
                                     [](benchmark::State& s) { clusteredBinning(s, int(s.range(0))); }),
        settings.quick ? std::vector<int>{16, 256} : std::vector<int>{16, 64, 256, 1024});
}

}  // namespace

int runPrepareBenchmarks(int argc, char** argv) {
  Settings settings;
  std::vector<std::string_view> given;
  for (int i = 1; i < argc; ++i) {
    if (std::string_view(argv[i]) == "--quick") settings.quick = true;
    else given.push_back(argv[i]);
  }
  std::vector<std::string> defaults = settings.defaultFlags();
  std::vector<char*> args = {argv[0]};
  for (std::string& d : defaults) args.push_back(d.data());
  for (std::string_view g : given) args.push_back(const_cast<char*>(g.data()));

  // Plain names (the bake curve's "/real_time" dropped) and no NaN in the JSON.
  const Reporters reporters = plainNameReporters(given);

  int count = int(args.size());
  args.push_back(nullptr);
  static bool registered = false;
  if (!registered) {
    registerAll(settings);
    registered = true;
  }
  benchmark::Initialize(&count, args.data());
  if (benchmark::ReportUnrecognizedArguments(count, args.data())) return app::kExitBadInput;
  benchmark::AddCustomContext("prepare_bench.set", settings.quick ? "quick" : "full");
  benchmark::RunSpecifiedBenchmarks(reporters.display.get(), reporters.file.get());
  benchmark::Shutdown();
  return 0;
}

}  // namespace bench
