// The frame benchmarks of one backend combination (SPEC 9, issue 7). Names
// and counters: docs/bench-format.md. What runs:
//   frame/<b>/lights64-1280x720/<mode>           mode: all-lights, per-object, legacy-4+4, and each
//                                                with the full shader (full-shader = all-lights);
//                                                deferred-hdr32, deferred-hdr16, deferred-ldr8
//   frame_readback/<b>/lights64-1280x720/<mode>
//   pipeline/<b>/lights64-1280x720/<mode>         preparePipeline with an empty cache
//   frame/<b>/curve-lights/all-lights/<n>         n = 1, 2, 4 ... 256 lights (the cut keeps 64), 640x360
//   frame/<b>/curve-lights/per-object/<n>
//   frame/<b>/curve-lights/deferred-<buffer>/<n>  hdr32, hdr16, ldr8: deferred against forward
//   frame/<b>/curve-resolution/all-lights/<WxH>   256x256, 640x360, 1280x720, 1920x1080, 64 lights
//   frame/<b>/curve-objects/all-lights/<n>        n = 1, 4, 16, 64, 256 tiles, 64 lights, 640x360
//   frame/<b>/<group>.<name>/<mode>               with --suite_scenes: every suite scene, frame 0
//   frame/<b>/lightmap-1280x720/lightmap-<n>      the plane's lightmap at n = 16 ... 512 texels a side,
//                                                with bake_ms; error against the lights in real time
//   frame/<b>/lightmap-1280x720/realtime          the same lights in real time
//   frame/<b>/lightmap-shadow-1280x720/<mode>     the same with one shadowed light: realtime, lightmap-64, -512
// softpipe (about 150 times slower than llvmpipe) runs a scaled-down set: the
// 64-light field in every mode but full-shader all-lights, `frame` only, one iteration
// times 3 repetitions, and the curves at 256x144 (resolution: 128x72 to
// 512x288), so that one softpipe process stays near 2 minutes.
#include "suite/bench/frame_benchmarks.h"

#include "backends/backend.h"
#include "baking/bake.h"
#include "lighting/frame.h"
#include "lighting/scene_loader.h"
#include "reference/bvh.h"
#include "reference/reference_renderer.h"
#include "reference/world_triangles.h"
#include "suite/bench/bench_scenes.h"
#include "suite/bench/deferred_load.h"
#include "suite/bench/image_error.h"
#include "suite/bench/lighting_cost.h"

#include <benchmark/benchmark.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>
#include <unistd.h>
#include <vector>

namespace bench {
namespace {

namespace fs = std::filesystem;
using namespace lighting;
using Clock = std::chrono::steady_clock;

constexpr int kExitSuccess = 0, kExitBadInput = 2, kExitNotSupported = 3, kExitInternalError = 4;

struct Settings {
  std::string backend = "vulkan";
  std::string driver;  // empty: the default (llvmpipe for GL; Vulkan has no choice here)
  std::optional<double> peakGflops;
  bool quick = false;
  bool suiteScenes = false;
  fs::path scenes = fs::path(LIGHTCTS_SOURCE_DIR) / "suite" / "scenes";
};

// How a benchmark repeats: a fixed iteration count, or Google Benchmark's
// own choice for at least minTime seconds (of the benchmark's time) per repetition.
struct Timing {
  int repetitions = 5;
  double minTime = 0.05;
  int iterations = 0;  // 0: chosen by Google Benchmark
};

// What a draw benchmark reports beside the time.
struct FrameLoad {
  double pixels = 0;
  // Per-pixel light evaluations, averaged over the image: each object's
  // per-pixel light count (Frame::lightsForObject: every kept light without
  // lists, kept directional + min(count, 8) with srp lists, list positions
  // 0-3 in the legacy profile) weighted by the pixels it covers, found by
  // one primary ray per sample on a grid of at most 256x256 samples (the
  // reference's BVH); background pixels count 0. Overdraw (a pixel shaded
  // twice before the depth test hides it) and vertex lights are not counted.
  // Deferred (SPEC 3.7): the light volumes that shade the pixel
  // (DeferredCoverage), not the lights of its object.
  double lightsPerPixel = 0;
  int keptLights = 0;
};

FrameLoad loadOf(const Frame& frame) {
  FrameLoad load;
  const int width = frame.view.width, height = frame.view.height;
  load.pixels = double(width) * height;
  load.keptLights = int(frame.selection.packed.directional.size() + frame.selection.packed.other.size());
  const int objects = int(frame.scene().objects.size());
  std::vector<double> perObject(std::size_t(objects), 0.0);
  for (int o = 0; o < objects; ++o) perObject[std::size_t(o)] = double(frame.lightsForObject(o).perPixel.size());
  std::optional<DeferredCoverage> deferred;
  if (frame.scene().pipeline.path == RenderPath::Deferred) deferred.emplace(frame);

  const reference::WorldTriangles world = reference::buildWorldTriangles(*frame.prepared);
  const reference::Bvh bvh(world);
  const int stride = std::max(1, int(std::ceil(std::sqrt(load.pixels / 65536.0))));
  double sum = 0, samples = 0;
  for (int j = stride / 2; j < height; j += stride) {
    for (int i = stride / 2; i < width; i += stride) {
      const Ray ray = frame.view.rayThroughPixel(i + 0.5, j + 0.5);
      const double cosine = glm::dot(ray.direction, frame.view.forward);
      const auto hit = bvh.nearestHit(ray, frame.view.camera.nearPlane / cosine, frame.view.camera.farPlane / cosine);
      if (hit && deferred) sum += deferred->volumesShading(ray, hit->t);
      else if (hit) sum += perObject[std::size_t(world.triangles[std::size_t(hit->triangle)].object)];
      samples += 1;
    }
  }
  load.lightsPerPixel = samples > 0 ? sum / samples : 0;
  return load;
}

// A prepared frame 0, its load and how it is drawn, kept for the whole run.
struct BenchFrame {
  std::shared_ptr<const PreparedScene> prepared;
  Frame frame;
  FrameLoad load;
  bool fullShader = false;   // draw with ShaderVariant::specialised = false
  std::string referenceKey;  // the cached ideal reference it is compared with; empty: no error counters
  std::string errorKey;      // the cached error (frame and frame_readback share it)
  // The scene whose ideal reference is the error's baseline when it is not
  // this one (the lightmap modes: the same lights in real time); null: this one.
  std::shared_ptr<const PreparedScene> referencePrepared;
  // The lightmap modes: the median time of a fresh bake (no cache) and how
  // many bakes it is the median of.
  std::optional<double> bakeMs;
  int bakeRuns = 0;
};

std::shared_ptr<const BenchFrame> makeBenchFrame(Scene scene, bool fullShader, std::string referenceKey,
                                                 std::string errorKey) {
  auto bench = std::make_shared<BenchFrame>();
  bench->prepared = baking::prepareBakedScene(std::move(scene));  // suite scenes may have lightmaps
  bench->frame = prepareFrame(bench->prepared, 0);
  bench->load = loadOf(bench->frame);
  bench->fullShader = fullShader;
  bench->referenceKey = std::move(referenceKey);
  bench->errorKey = std::move(errorKey);
  return bench;
}

// Everything of this process's run: the combination, its backends, the
// ideal references and errors computed so far.
struct Run {
  Settings settings;
  const backends::BackendEntry* entry = nullptr;
  backends::BackendOptions options;
  std::string suffix;  // vulkan, gl-egl, gl-osmesa-softpipe, ...
  bool slow = false;   // softpipe: the scaled-down set
  fs::path cacheDir;
  double flopsPerPixelLight = 0;  // 0: unknown, no limit counters
  std::unique_ptr<backends::Backend> specialised;  // the shipped shaders
  std::unique_ptr<backends::Backend> full;         // full-shader, made on first use
  std::map<std::string, imaging::Image> ideal;
  std::map<std::string, ImageError> errors;
  std::map<const backends::Backend*, const BenchFrame*> lastDrawn;  // what each backend drew last
  bool deviceTime = false;  // the benchmarks' time is the device's (calibrateTimeSource)

  backends::Backend& backendFor(const BenchFrame& bench) {
    if (!bench.fullShader) return *specialised;
    if (!full) {
      backends::BackendOptions fullOptions = options;
      fullOptions.variant.specialised = false;
      full = entry->create(fullOptions);
    }
    return *full;
  }

  // The `--ideal` reference of SPEC 6, rendered once per key in this process.
  const imaging::Image& idealFor(const BenchFrame& bench) {
    auto it = ideal.find(bench.referenceKey);
    if (it == ideal.end()) {
      const reference::ReferenceOptions idealOptions{.ideal = true};
      if (bench.referencePrepared) {
        const reference::ReferenceRenderer renderer(bench.referencePrepared);
        const Frame frame = prepareFrame(bench.referencePrepared, bench.frame.index);
        it = ideal.emplace(bench.referenceKey, renderer.render(frame, idealOptions).value).first;
      } else {
        const reference::ReferenceRenderer renderer(bench.prepared);
        it = ideal.emplace(bench.referenceKey, renderer.render(bench.frame, idealOptions).value).first;
      }
    }
    return it->second;
  }
};

// prefix + text, appended: GCC 12 warns falsely (-Wrestrict) on `"literal" + std::string&&`.
std::string joined(const char* prefix, const std::string& text) {
  std::string out(prefix);
  out += text;
  return out;
}

double milliseconds(Clock::duration d) { return std::chrono::duration<double, std::milli>(d).count(); }

void setLoadCounters(benchmark::State& state, const Run& run, const FrameLoad& load) {
  auto& c = state.counters;
  const double iterations = double(state.iterations());
  c["pixels"] = load.pixels;
  c["lights"] = double(load.keptLights);
  c["lights_per_pixel"] = load.lightsPerPixel;
  c["pixels_per_s"] = benchmark::Counter(load.pixels * iterations, benchmark::Counter::kIsRate);
  c["pixel_light_evals_per_s"] =
      benchmark::Counter(load.pixels * load.lightsPerPixel * iterations, benchmark::Counter::kIsRate);
  if (run.settings.peakGflops && run.flopsPerPixelLight > 0) {
    c["flops_per_pixel_light"] = run.flopsPerPixelLight;
    c["limit_ms"] = load.pixels * load.lightsPerPixel * run.flopsPerPixelLight / (*run.settings.peakGflops * 1e9) * 1e3;
  }
}

// Draw (and read back) on the backend object shared by every draw benchmark
// of the run. Untimed first: the ideal reference (cached), the pipeline, and
// (but on softpipe, where one frame takes seconds) one draw that uploads the
// geometry, allocates the targets and lets the driver finish its compile.
// The loop then times steady-state frames (uniform packing and upload
// included: draw() does it every call). The benchmark's time is the device's
// own time of the draw when the backend reports one that can be trusted
// (Run::deviceTime; `frame` only: the readback is not in it), else
// wall-clock time; `wall_ms` is always there, `device_ms` when reported.
void runFrame(benchmark::State& state, Run& run, const BenchFrame& bench, bool withReadback) {
  try {
    backends::Backend& backend = run.backendFor(bench);
    const imaging::Image* ideal = bench.referenceKey.empty() ? nullptr : &run.idealFor(bench);
    backend.preparePipeline(bench.frame);
    // Repetitions call this again: the warm-up draw is needed only when
    // another frame was drawn on this backend since.
    if (!run.slow && run.lastDrawn[&backend] != &bench) backend.draw(bench.frame);
    run.lastDrawn[&backend] = &bench;
    double wallMs = 0, deviceMs = 0;
    bool deviceEveryTime = true;
    imaging::Image image;  // frame_readback: the last one read back
    for (auto _ : state) {
      const auto start = Clock::now();
      backend.draw(bench.frame);
      const std::optional<double> device = backend.lastDrawDeviceMilliseconds();
      if (withReadback) {
        image = backend.readback();
        benchmark::DoNotOptimize(image.pixels.data());
      }
      const double wall = milliseconds(Clock::now() - start);
      wallMs += wall;
      if (device) deviceMs += *device;
      else deviceEveryTime = false;
      state.SetIterationTime((run.deviceTime && device && !withReadback ? *device : wall) / 1e3);
    }
    auto& c = state.counters;
    c["wall_ms"] = benchmark::Counter(wallMs, benchmark::Counter::kAvgIterations);
    if (deviceEveryTime && state.iterations() > 0)
      c["device_ms"] = benchmark::Counter(deviceMs, benchmark::Counter::kAvgIterations);
    setLoadCounters(state, run, bench.load);
    if (ideal) {
      auto it = run.errors.find(bench.errorKey);
      if (it == run.errors.end()) {
        if (!withReadback || image.pixels.empty()) image = backend.readback();  // one readback per draw
        it = run.errors.emplace(bench.errorKey, compareToIdeal(image, *ideal)).first;
      }
      const ImageError& e = it->second;
      c["err_rmse"] = e.rmse;
      c["err_max_abs"] = e.maxAbs;
      c["err_psnr_db"] = e.psnrDb;
      c["err_perceptual_fail"] = e.perceptualFail;
    }
    if (bench.bakeMs) {
      c["bake_ms"] = *bench.bakeMs;
      c["bake_runs"] = double(bench.bakeRuns);
      c["lightmap_texels"] = double(bench.frame.scene().objects.front().lightmapResolution) *
                             double(bench.frame.scene().objects.front().lightmapResolution);
    }
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
  }
}

void removeContents(const fs::path& dir) {
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec)) fs::remove_all(entry.path(), ec);
}

// Pipelines are cached per backend object (in memory) and in the on-disk
// cache folder, so every iteration empties the folder and creates a fresh
// backend, neither of them timed (manual time): only preparePipeline() is
// measured, writing the pipeline cache back to the folder included. Drivers
// that compile state-dependent variants (lavapipe) finish part of their
// compile in the first draw, which this does not time.
void runPipeline(benchmark::State& state, Run& run, const BenchFrame& bench) {
  try {
    backends::BackendOptions options = run.options;
    options.variant.specialised = !bench.fullShader;
    for (auto _ : state) {
      removeContents(run.cacheDir);
      const std::unique_ptr<backends::Backend> backend = run.entry->create(options);
      const auto start = Clock::now();
      backend->preparePipeline(bench.frame);
      state.SetIterationTime(milliseconds(Clock::now() - start) / 1e3);
    }
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }
  state.counters["lights"] = double(bench.load.keptLights);
}

double minimum(const std::vector<double>& v) { return v.empty() ? 0.0 : *std::min_element(v.begin(), v.end()); }
double maximum(const std::vector<double>& v) { return v.empty() ? 0.0 : *std::max_element(v.begin(), v.end()); }

// Repetitions with aggregates (mean, median, stddev, cv, min, max) in the
// JSON beside every repetition (the compare tool's U-test needs those); the
// console shows the aggregates only.
void configure(benchmark::internal::Benchmark* b, const Timing& timing) {
  b->Unit(benchmark::kMillisecond)->UseManualTime()->Repetitions(timing.repetitions)->DisplayAggregatesOnly(true);
  b->ComputeStatistics("min", minimum)->ComputeStatistics("max", maximum);
  if (timing.iterations > 0) b->Iterations(timing.iterations);
  else b->MinTime(timing.minTime);
}

class Registrar {
 public:
  Registrar(std::shared_ptr<Run> run) : run_(std::move(run)) {
    const bool quick = run_->settings.quick;
    if (run_->slow) {
      frameTiming_ = {quick ? 1 : 3, 0, 1};
      pipelineTiming_ = {quick ? 1 : 3, 0.05, 0};
    } else {
      frameTiming_ = {quick ? 2 : 5, quick ? 0.01 : 0.05, 0};
      pipelineTiming_ = frameTiming_;
    }
  }

  void frame(const std::string& scene, const std::string& mode, const std::string& x,
             const std::shared_ptr<const BenchFrame>& bench, bool withReadback) {
    const std::string name = std::string(withReadback ? "frame_readback/" : "frame/") + run_->suffix + "/" + scene +
                             "/" + mode + (x.empty() ? "" : "/" + x);
    auto run = run_;
    configure(benchmark::RegisterBenchmark(name.c_str(),
                                           [run, bench, withReadback](benchmark::State& st) {
                                             runFrame(st, *run, *bench, withReadback);
                                           }),
              frameTiming_);
  }

  // A frame benchmark whose scene is made on its first run, not here: the
  // lightmap modes bake (several times) and trace their load only when the
  // filter selects them, so the smoke tests do not pay for every resolution.
  using MakeBench = std::function<std::shared_ptr<const BenchFrame>()>;
  void lazyFrame(const std::string& scene, const std::string& mode, MakeBench make) {
    const std::string name = "frame/" + run_->suffix + "/" + scene + "/" + mode;
    auto run = run_;
    auto made = std::make_shared<std::shared_ptr<const BenchFrame>>();
    configure(benchmark::RegisterBenchmark(name.c_str(),
                                           [run, made, make = std::move(make)](benchmark::State& st) {
                                             try {
                                               if (!*made) *made = make();
                                             } catch (const std::exception& e) {
                                               st.SkipWithError(e.what());
                                               return;
                                             }
                                             runFrame(st, *run, **made, false);
                                           }),
              frameTiming_);
  }

  void pipeline(const std::string& scene, const std::string& mode, const std::shared_ptr<const BenchFrame>& bench) {
    const std::string name = "pipeline/" + run_->suffix + "/" + scene + "/" + mode;
    auto run = run_;
    configure(benchmark::RegisterBenchmark(name.c_str(),
                                           [run, bench](benchmark::State& st) { runPipeline(st, *run, *bench); }),
              pipelineTiming_);
  }

  const Run& run() const { return *run_; }

 private:
  std::shared_ptr<Run> run_;
  Timing frameTiming_, pipelineTiming_;
};

// SPEC 5.1: srp keeps up to 64 point/spot lights, legacy 16; the synthetic
// scenes put every light in view, so the cut must keep min(lights, budget).
void checkKept(const BenchFrame& bench) {
  const Scene& scene = bench.frame.scene();
  const int budget = scene.pipeline.profile == Profile::Legacy ? 16 : 64;
  const std::size_t expected = std::min<std::size_t>(scene.lights.size(), std::size_t(budget));
  const std::size_t kept = bench.frame.selection.packed.other.size();
  if (kept != expected)
    std::fprintf(stderr, "render_bench: synthetic scene %s keeps %zu point/spot lights, not %zu\n",
                 scene.name.c_str(), kept, expected);
}

// The 1280x720 64-light field in every mode: frame, frame_readback (not on
// softpipe), pipeline. Error counters against the ideal reference of the
// field (one per profile: all-lights, per-object and full-shader share one).
struct ModeBenches {
  std::vector<std::pair<std::string, std::shared_ptr<const BenchFrame>>> shipped, full, pipeline;
};

// The modes of the speed-against-error plot: each profile and light path as
// shipped (specialised shader), and with the full shader, which shows what
// specialization buys; the deferred path in each light buffer (SPEC 3.7),
// whose error against the same ideal reference as all-lights is what the
// buffer's format costs. softpipe skips the slowest, full-shader all-lights
// (some 30 s a frame), and still has eight.
struct ModeSpec {
  FrameMode scene;  // which field: all lights, per-object lists, legacy
  bool fullShader;
  std::string name;
};

ModeBenches modeBenches(const Run& run) {
  const std::string scene = "lights64-1280x720";
  std::vector<ModeSpec> modes = {{FrameMode::AllLights, false, "all-lights"},
                                 {FrameMode::PerObject, false, "per-object"},
                                 {FrameMode::Legacy4x4, false, "legacy-4+4"},
                                 {FrameMode::PerObject, true, "per-object-full-shader"},
                                 {FrameMode::Legacy4x4, true, "legacy-4+4-full-shader"}};
  if (!run.slow) modes.insert(modes.begin() + 3, {FrameMode::AllLights, true, "full-shader"});
  if (run.settings.quick) modes.resize(2);
  for (const FrameMode deferred : {FrameMode::DeferredHdr32, FrameMode::DeferredHdr16, FrameMode::DeferredLdr8})
    modes.push_back({deferred, false, std::string(modeName(deferred))});
  ModeBenches benches;
  for (const ModeSpec& mode : modes) {
    FieldSpec spec;
    spec.mode = mode.scene;
    const std::string referenceKey = scene + (mode.scene == FrameMode::Legacy4x4 ? "/legacy" : "/srp");
    std::shared_ptr<const BenchFrame> bench = makeBenchFrame(fieldScene(spec, scene + "-" + mode.name),
                                                             mode.fullShader, referenceKey, scene + "/" + mode.name);
    if (deferredBufferOf(mode.scene)) {
      // The deferred modes share the srp reference of the forward field, made
      // from that scene whichever mode runs first: a deferred scene's own
      // reference includes its buffer's saturation (ldr8), which is part of
      // the error a buffer costs.
      auto withForwardReference = std::make_shared<BenchFrame>(*bench);
      FieldSpec forward = spec;
      forward.mode = FrameMode::AllLights;
      withForwardReference->referencePrepared = prepareScene(fieldScene(forward, scene + "-forward-reference"));
      bench = std::move(withForwardReference);
    }
    checkKept(*bench);
    (mode.fullShader ? benches.full : benches.shipped).emplace_back(mode.name, bench);
    if (mode.name == "all-lights" || !(run.slow || run.settings.quick)) benches.pipeline.emplace_back(mode.name, bench);
  }
  return benches;
}

void registerModes(Registrar& r, const std::vector<std::pair<std::string, std::shared_ptr<const BenchFrame>>>& benches) {
  for (const auto& [mode, bench] : benches) {
    r.frame("lights64-1280x720", mode, "", bench, false);
    if (!r.run().slow) r.frame("lights64-1280x720", mode, "", bench, true);
  }
}

// A bake that neither reads nor writes the bake cache: a fresh one, timed whole.
baking::BakeOptions freshBake() {
  baking::BakeOptions options;
  options.useCache = false;
  return options;
}

// The lightmap modes (SPEC 9: baked lightmaps at several resolutions): the
// lightmap scene with its lights baked into an N x N map, drawn like any
// frame, its error taken against the ideal reference of the same lights in
// real time, so the error is what the bake loses (the map's resolution,
// bilinear filtering, and any shadow, which real time does not draw). bake_ms is
// the median of fresh bakes (no cache, every core), repeated while they are
// cheap: up to 5 (3 with --quick) within about a second (0.2 s).
std::shared_ptr<const BenchFrame> makeLightmapBench(bool quick, const LightmapSpec& spec, const std::string& scene,
                                                    const std::string& mode,
                                                    const std::shared_ptr<const PreparedScene>& realtime) {
  const auto unbaked = prepareScene(lightmapScene(spec, scene + "-" + mode));
  const int maxRuns = quick ? 3 : 5;
  const double budgetMs = quick ? 200 : 1000;
  std::vector<double> times;
  std::shared_ptr<const BakedLighting> baked;
  double spentMs = 0;
  do {
    const auto start = Clock::now();
    baked = baking::bakeScene(*unbaked, freshBake());
    times.push_back(milliseconds(Clock::now() - start));
    spentMs += times.back();
  } while (int(times.size()) < maxRuns && spentMs < budgetMs);
  std::sort(times.begin(), times.end());
  const std::size_t n = times.size();

  auto bench = std::make_shared<BenchFrame>();
  bench->prepared = baking::withBake(*unbaked, baked);
  bench->frame = prepareFrame(bench->prepared, 0);
  bench->load = loadOf(bench->frame);
  bench->referenceKey = scene + "/realtime";
  bench->errorKey = scene + "/" + mode;
  bench->referencePrepared = realtime;
  bench->bakeMs = n % 2 ? times[n / 2] : 0.5 * (times[n / 2 - 1] + times[n / 2]);
  bench->bakeRuns = int(n);
  return bench;
}

// One lightmap scene: its `realtime` point and a `lightmap-N` point per N.
void registerLightmapScene(Registrar& r, const LightmapSpec& spec, const std::string& scene,
                           const std::vector<int>& resolutions) {
  LightmapSpec realtimeSpec = spec;
  realtimeSpec.baked = false;
  const auto realtime = prepareScene(lightmapScene(realtimeSpec, scene + "-realtime"));
  r.lazyFrame(scene, "realtime", [realtime, scene] {
    auto bench = std::make_shared<BenchFrame>();
    bench->prepared = realtime;
    bench->frame = prepareFrame(realtime, 0);
    bench->load = loadOf(bench->frame);
    bench->referenceKey = bench->errorKey = scene + "/realtime";
    return std::shared_ptr<const BenchFrame>(bench);
  });
  const bool quick = r.run().settings.quick;
  for (const int n : resolutions) {
    LightmapSpec baked = spec;
    baked.resolution = n;
    const std::string mode = joined("lightmap-", std::to_string(n));
    r.lazyFrame(scene, mode, [quick, baked, scene, mode, realtime] {
      return makeLightmapBench(quick, baked, scene, mode, realtime);
    });
  }
}

// `lightmap-WxH`: no shadow, so the error against real time is the map's
// alone and falls with N all the way. `lightmap-shadow-WxH`: the same with
// the shadowed light, at two resolutions: the shadow, which real time does not
// draw, is an error floor that a finer map cannot remove, and the bake casts
// shadow rays. --quick and softpipe: the first at 320x180, N = 16 and 128.
void registerLightmapModes(Registrar& r) {
  const Run& run = r.run();
  const bool small = run.slow || run.settings.quick;
  LightmapSpec spec;
  spec.shadows = false;
  // softpipe (its frames take seconds) and --quick (a smoke test): a
  // sixteenth of the pixels; the world is the same (the field keeps 16:9).
  if (small) spec.width = 320, spec.height = 180;
  const std::string size = std::to_string(spec.width) + "x" + std::to_string(spec.height);
  std::vector<int> resolutions(std::begin(kLightmapResolutions), std::end(kLightmapResolutions));
  if (small) resolutions = {16, 128};
  registerLightmapScene(r, spec, joined("lightmap-", size), resolutions);
  if (small) return;
  spec.shadows = true;
  registerLightmapScene(r, spec, joined("lightmap-shadow-", size), {64, 512});
}

// The cost curves: speed only (no error counters: an ideal reference per
// point would cost more than the whole curve).
void registerCurves(Registrar& r) {
  const Run& run = r.run();
  const bool quick = run.settings.quick;
  // The light and object curves at 640x360 (a quarter of the field's
  // pixels, to fit the time budget), at 256x144 on softpipe.
  const int curveWidth = run.slow ? 256 : 640, curveHeight = run.slow ? 144 : 360;

  const std::vector<int> lightCounts =
      quick ? std::vector<int>{1, 64, 256} : std::vector<int>{1, 2, 4, 8, 16, 32, 64, 128, 256};
  // Deferred against forward along the light count: where the volumes
  // (a few per pixel) overtake every kept light per pixel.
  std::vector<FrameMode> lightModes = {FrameMode::AllLights};
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
      const auto bench =
          makeBenchFrame(fieldScene(spec, joined("curve-lights-", std::to_string(n) + "-" + std::string(modeName(mode)))),
                         false, "", "");
      checkKept(*bench);
      r.frame("curve-lights", std::string(modeName(mode)), std::to_string(n), bench, false);
    }
  }

  std::vector<std::pair<int, int>> sizes;
  if (run.slow) sizes = {{128, 72}, {256, 144}, {512, 288}};
  else sizes = {{256, 256}, {640, 360}, {1280, 720}, {1920, 1080}};
  if (quick) sizes.resize(2);
  for (const auto& [w, h] : sizes) {
    FieldSpec spec;
    spec.width = w;
    spec.height = h;
    const std::string x = std::to_string(w) + "x" + std::to_string(h);
    const auto bench = makeBenchFrame(fieldScene(spec, "curve-resolution-" + x), false, "", "");
    checkKept(*bench);
    r.frame("curve-resolution", "all-lights", x, bench, false);
  }

  const std::vector<int> sides = quick ? std::vector<int>{1, 8} : std::vector<int>{1, 2, 4, 8, 16};
  for (const int side : sides) {
    FieldSpec spec;
    spec.width = curveWidth;
    spec.height = curveHeight;
    spec.tileColumns = spec.tileRows = side;
    spec.boxes = false;
    const std::string x = std::to_string(side * side);
    const auto bench = makeBenchFrame(fieldScene(spec, "curve-objects-" + x), false, "", "");
    checkKept(*bench);
    r.frame("curve-objects", "all-lights", x, bench, false);
  }
}

std::string suiteMode(const Scene& scene) {
  if (scene.pipeline.path == RenderPath::Deferred) {
    switch (scene.pipeline.deferredBuffer) {
      case DeferredBuffer::Hdr32: return "deferred-hdr32";
      case DeferredBuffer::Hdr16: return "deferred-hdr16";
      case DeferredBuffer::Ldr8: return "deferred-ldr8";
    }
  }
  if (scene.pipeline.profile == Profile::Legacy) return "legacy-4+4";
  return scene.pipeline.lightsPerObject ? "per-object" : "all-lights";
}

// --suite_scenes: frame 0 of every suite scene, `frame` kind, with its error
// against its own ideal reference.
void registerSuiteScenes(Registrar& r) {
  const fs::path& root = r.run().settings.scenes;
  std::vector<fs::path> files;
  std::error_code ec;
  for (const auto& group : fs::directory_iterator(root, ec)) {
    if (!group.is_directory()) continue;
    for (const auto& file : fs::directory_iterator(group.path(), ec))
      if (file.path().extension() == ".json") files.push_back(file.path());
  }
  if (files.empty()) std::fprintf(stderr, "render_bench: no suite scenes in %s\n", root.c_str());
  std::sort(files.begin(), files.end());
  for (const fs::path& file : files) {
    const std::string sceneId = file.parent_path().filename().string() + "." + file.stem().string();
    try {
      Scene scene = loadSceneFile(file.string());
      const std::string mode = suiteMode(scene);
      const auto bench = makeBenchFrame(std::move(scene), false, sceneId, sceneId);
      r.frame(sceneId, mode, "", bench, false);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "render_bench: %s not registered: %s\n", sceneId.c_str(), e.what());
    }
  }
}

// Google Benchmark appends the per-benchmark settings to every name
// ("/min_time:0.050/repeats:5/manual_time"); docs/bench-format.md's names
// have none, so the reporters drop them. (--benchmark_filter still sees them:
// end a pattern with `(/|$)`, not `$`.)
template <class Base>
class PlainNames : public Base {
 public:
  using Base::Base;
  void ReportRuns(const std::vector<benchmark::BenchmarkReporter::Run>& runs) override {
    std::vector<benchmark::BenchmarkReporter::Run> plain = runs;
    for (auto& run : plain) {
      run.run_name.min_time.clear();
      run.run_name.min_warmup_time.clear();
      run.run_name.iterations.clear();
      run.run_name.repetitions.clear();
      run.run_name.time_type.clear();
      // The cv aggregate of a counter that is 0 every time (err_perceptual_fail
      // of a clean image) is 0/0; JSON has no NaN, and nothing varied: 0.
      for (auto& [name, counter] : run.counters)
        if (!std::isfinite(counter.value)) counter.value = 0;
    }
    Base::ReportRuns(plain);
  }
};

// Whether the device's time can be the benchmarks' time. On llvmpipe, GL's
// GL_TIME_ELAPSED covers only part of the work (about a tenth of a frame
// that glFinish waits for), while Vulkan's timestamps on lavapipe match the
// wall-clock time of the draw. So three untimed draws of a small field, and
// the device's time is used when the last one reports at least half the
// wall-clock time. Returns the line for the JSON context.
std::string calibrateTimeSource(Run& run) {
  FieldSpec spec;
  spec.width = run.slow ? 128 : 640;
  spec.height = run.slow ? 72 : 360;
  auto bench = makeBenchFrame(fieldScene(spec, "time-calibration"), false, "", "");
  backends::Backend& backend = *run.specialised;
  std::optional<double> device;
  double wall = 0;
  for (int i = 0; i < 3; ++i) {
    const auto start = Clock::now();
    backend.draw(bench->frame);
    device = backend.lastDrawDeviceMilliseconds();
    wall = milliseconds(Clock::now() - start);
  }
  run.deviceTime = device && *device >= 0.5 * wall;
  char text[320];
  if (!device)
    std::snprintf(text, sizeof text, "wall: the device reports no time of its own");
  else if (run.deviceTime)
    std::snprintf(text, sizeof text, "device (frame kind): %.3g ms of device time for %.3g ms wall on a %dx%d calibration frame",
                  *device, wall, spec.width, spec.height);
  else
    std::snprintf(text, sizeof text,
                  "wall: the device's time misses most of the work (%.3g ms for %.3g ms wall on a %dx%d calibration "
                  "frame); device_ms is reported beside",
                  *device, wall, spec.width, spec.height);
  return text;
}

bool startsWith(std::string_view a, std::string_view prefix, std::string_view& value) {
  if (!a.starts_with(prefix)) return false;
  value = a.substr(prefix.size());
  return true;
}

}  // namespace

int runFrameBenchmarks(int argc, char** argv) {
  auto run = std::make_shared<Run>();
  Settings& settings = run->settings;
  std::vector<char*> arguments;
  for (int i = 0; i < argc; ++i) {
    const std::string_view a(argv[i]);
    std::string_view value;
    if (i > 0 && startsWith(a, "--backend=", value)) settings.backend = std::string(value);
    else if (i > 0 && startsWith(a, "--driver=", value)) settings.driver = std::string(value);
    else if (i > 0 && startsWith(a, "--scenes=", value)) settings.scenes = fs::path(value);
    else if (i > 0 && startsWith(a, "--peak_gflops=", value)) {
      char* end = nullptr;
      const std::string text(value);
      const double gflops = std::strtod(text.c_str(), &end);
      if (end == text.c_str() || *end != '\0' || !(gflops > 0)) {
        std::fprintf(stderr, "render_bench: --peak_gflops needs a positive number, not '%s'\n", text.c_str());
        return kExitBadInput;
      }
      settings.peakGflops = gflops;
    } else if (i > 0 && a == "--quick") settings.quick = true;
    else if (i > 0 && a == "--suite_scenes") settings.suiteScenes = true;
    else arguments.push_back(argv[i]);
  }
  if (settings.backend != "vulkan" && settings.backend != "gl-egl" && settings.backend != "gl-osmesa") {
    std::fprintf(stderr, "render_bench: --backend must be vulkan, gl-egl or gl-osmesa, not '%s'\n",
                 settings.backend.c_str());
    return kExitBadInput;
  }
  if (!settings.driver.empty() && settings.driver != "llvmpipe" && settings.driver != "softpipe") {
    std::fprintf(stderr, "render_bench: --driver must be llvmpipe or softpipe, not '%s'\n", settings.driver.c_str());
    return kExitBadInput;
  }
  const bool gl = settings.backend != "vulkan";
  if (!gl && settings.driver == "softpipe") {
    std::fprintf(stderr, "render_bench: --driver=softpipe is for the GL backends only\n");
    return kExitBadInput;
  }
  run->suffix = settings.backend + (settings.driver == "softpipe" ? "-softpipe" : "");
  run->slow = settings.driver == "softpipe";
  if (gl) run->options.driver = settings.driver;
  run->flopsPerPixelLight = flopsPerPixelLight();

  run->entry = backends::findCompiledBackend(settings.backend);
  if (!run->entry) {
    std::fprintf(stderr, "render_bench: %s: not compiled into this build (NotSupported)\n", run->suffix.c_str());
    return kExitNotSupported;
  }

  // The pipeline benchmarks must measure a real compile, not a hit in the
  // on-disk pipeline cache ($LIGHTCTS_CACHE_DIR, else ~/.cache/lightcts):
  // point the cache at a fresh, empty folder of this process before any
  // backend is created (runPipeline empties it again before every
  // iteration), and remove it at the end. The user's cache stays untouched.
  const fs::path cacheDir = fs::temp_directory_path() / joined("lightcts-render-bench-cache-", std::to_string(::getpid()));
  run->cacheDir = cacheDir;
  fs::remove_all(run->cacheDir);
  fs::create_directories(run->cacheDir);
  ::setenv("LIGHTCTS_CACHE_DIR", run->cacheDir.c_str(), 1);
  auto cleanUp = [&] {
    benchmark::ClearRegisteredBenchmarks();
    run.reset();  // the backends go before their cache folder
    std::error_code ec;
    fs::remove_all(cacheDir, ec);
  };

  // Validation stays off (BackendOptions default): it would time the layers, not the driver.
  try {
    run->specialised = run->entry->create(run->options);
  } catch (const backends::NotSupportedError& e) {
    std::fprintf(stderr, "render_bench: %s: %s (NotSupported)\n", run->suffix.c_str(), e.what());
    cleanUp();
    return kExitNotSupported;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "render_bench: %s: %s\n", run->suffix.c_str(), e.what());
    cleanUp();
    return kExitInternalError;
  }
  const backends::DeviceInfo info = run->specialised->device();
  benchmark::AddCustomContext("backend", run->suffix);
  benchmark::AddCustomContext(run->suffix + ".device", info.name);
  benchmark::AddCustomContext(run->suffix + ".driver", info.driver);
  benchmark::AddCustomContext(run->suffix + ".driver_version", info.driverVersion);
  benchmark::AddCustomContext(run->suffix + ".api", info.apiVersion);
  benchmark::AddCustomContext("frame_bench.set", std::string(run->slow ? "softpipe (scaled down)" : "full") +
                                                     (settings.quick ? ", quick" : ""));
  try {
    benchmark::AddCustomContext("frame_bench.time", calibrateTimeSource(*run));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "render_bench: %s: the calibration draw failed: %s\n", run->suffix.c_str(), e.what());
    cleanUp();
    return kExitInternalError;
  }
  benchmark::AddCustomContext("frame_bench.error",
                              "against the --ideal reference over its compared pixels; PSNR peak = max of the "
                              "ideal RGB; perceptual: compare_Yee, 100 cd/m2, 45 deg field of view");
  if (settings.peakGflops) benchmark::AddCustomContext("frame_bench.peak_gflops", std::to_string(*settings.peakGflops));

  try {
    Registrar registrar(run);
    // Google Benchmark runs them in this order. A GL backend makes its
    // context current when it is created and never again, and a destroyed
    // one leaves none current: so every benchmark of the shipped-shader
    // backend first, then full-shader (its backend is created on first use),
    // then pipeline (a fresh backend per iteration).
    const ModeBenches modes = modeBenches(*run);
    registerModes(registrar, modes.shipped);
    registerLightmapModes(registrar);
    registerCurves(registrar);
    if (settings.suiteScenes) registerSuiteScenes(registrar);
    registerModes(registrar, modes.full);
    for (const auto& [mode, bench] : modes.pipeline) registrar.pipeline("lights64-1280x720", mode, bench);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "render_bench: preparing the benchmark scenes failed: %s\n", e.what());
    cleanUp();
    return kExitInternalError;
  }

  // The reporters (PlainNames): the console's, unless --benchmark_format
  // asks for another; the file's when --benchmark_out writes JSON (the
  // default format). CSV keeps Google Benchmark's own, names unchanged.
  std::string displayFormat = "console", outFormat = "json";
  bool outFile = false;
  for (std::size_t i = 1; i < arguments.size(); ++i) {
    const std::string_view a(arguments[i]);
    std::string_view value;
    if (startsWith(a, "--benchmark_format=", value)) displayFormat = std::string(value);
    else if (startsWith(a, "--benchmark_out_format=", value)) outFormat = std::string(value);
    else if (startsWith(a, "--benchmark_out=", value)) outFile = !value.empty();
  }
  std::unique_ptr<benchmark::BenchmarkReporter> display, file;
  if (displayFormat == "console")
    display = std::make_unique<PlainNames<benchmark::ConsoleReporter>>(
        ::isatty(STDOUT_FILENO) ? benchmark::ConsoleReporter::OO_ColorTabular : benchmark::ConsoleReporter::OO_Tabular);
  else if (displayFormat == "json")
    display = std::make_unique<PlainNames<benchmark::JSONReporter>>();
  if (outFile && outFormat == "json") file = std::make_unique<PlainNames<benchmark::JSONReporter>>();

  int count = int(arguments.size());
  arguments.push_back(nullptr);
  benchmark::Initialize(&count, arguments.data());
  int status = kExitBadInput;
  if (!benchmark::ReportUnrecognizedArguments(count, arguments.data())) {
    benchmark::RunSpecifiedBenchmarks(display.get(), file.get());
    status = kExitSuccess;
  }
  benchmark::Shutdown();
  cleanUp();
  return status;
}

}  // namespace bench
