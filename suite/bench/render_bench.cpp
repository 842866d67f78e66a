// Speed of the rendering backends (SPEC 9), with Google Benchmark. For every
// backend compiled in that can be created on this machine:
//   BM_Draw/<backend>/<group>/<name>           draw only (record, submit, wait)
//   BM_DrawReadback/<backend>/<group>/<name>   draw + copy the image back
//   BM_PipelineCompile/<backend>/<group>/<name> preparePipeline with an empty cache
//   BM_CompileAndFirstDraw/<backend>/<group>/<name> the same plus the first draw
// for every scene of suite/scenes/*/*.json (frame 0), plus a synthetic
// 1280x720 scene with 64 point lights over a field of 80 objects, drawn with
// all lights per pixel (`-all`) and with per-object lists (`-per-object`).
// Every benchmark repeats 5 times and reports aggregates (median included);
// times are wall-clock, since the device works in threads of its own.
#include "backends/backend.h"
#include "lighting/frame.h"
#include "lighting/scene_loader.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <memory>
#include <string>
#include <system_error>
#include <unistd.h>
#include <vector>

namespace {

namespace fs = std::filesystem;
using namespace lighting;

constexpr int kRepetitions = 5;
constexpr double kMinTimeSeconds = 0.05;  // per repetition; keeps the whole run short on a CPU device

// What a draw benchmark reports beside the time.
struct FrameLoad {
  double pixels = 0;
  // Light evaluations per pixel, an estimate: the number of per-pixel lights
  // each object gets (Frame::lightsForObject: every kept light without lists,
  // kept directional + min(count, 8) with srp lists, list positions 0-3 in the
  // legacy profile), averaged over the objects with equal weight. The true sum
  // would weigh each object by the pixels it covers (and count overdraw); the
  // estimate ignores coverage. Vertex lights are not counted.
  double lightsPerPixel = 0;
  int keptLights = 0;
};

FrameLoad loadOf(const Frame& frame) {
  FrameLoad load;
  load.pixels = double(frame.scene().image.width) * frame.scene().image.height;
  load.keptLights = int(frame.selection.packed.directional.size() + frame.selection.packed.other.size());
  const int objects = int(frame.scene().objects.size());
  double sum = 0;
  for (int o = 0; o < objects; ++o) sum += double(frame.lightsForObject(o).perPixel.size());
  load.lightsPerPixel = objects > 0 ? sum / objects : 0;
  return load;
}

// A prepared frame 0 and its load, kept alive for the whole run.
struct BenchFrame {
  std::shared_ptr<const PreparedScene> prepared;
  Frame frame;
  FrameLoad load;
};

std::shared_ptr<const BenchFrame> makeBenchFrame(Scene scene) {
  auto bench = std::make_shared<BenchFrame>();
  bench->prepared = prepareScene(std::move(scene));
  bench->frame = prepareFrame(bench->prepared, 0);
  bench->load = loadOf(bench->frame);
  return bench;
}

void setCounters(benchmark::State& state, const FrameLoad& load) {
  const double iterations = double(state.iterations());
  state.counters["pixels_per_s"] = benchmark::Counter(load.pixels * iterations, benchmark::Counter::kIsRate);
  state.counters["pixel_light_evals_per_s"] =
      benchmark::Counter(load.pixels * load.lightsPerPixel * iterations, benchmark::Counter::kIsRate);
  state.counters["lights"] = double(load.keptLights);
}

// Draw (and read back) on one backend object shared by every draw benchmark
// of that backend. The first draw, untimed, builds the pipeline, uploads the
// geometry and allocates the targets; the loop then times steady-state frames
// (uniform packing and upload included: draw() does it every call).
void runDraw(benchmark::State& state, backends::Backend* backend, std::shared_ptr<const BenchFrame> bench,
             bool withReadback) {
  try {
    backend->preparePipeline(bench->frame);
    backend->draw(bench->frame);
    if (withReadback) benchmark::DoNotOptimize(backend->readback().pixels.data());
    for (auto _ : state) {
      backend->draw(bench->frame);
      if (withReadback) {
        const imaging::Image image = backend->readback();
        benchmark::DoNotOptimize(image.pixels.data());
      }
    }
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }
  setCounters(state, bench->load);
}

void removeContents(const fs::path& dir) {
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec)) fs::remove_all(entry.path(), ec);
}

// Pipelines are cached per backend object (in memory) and in the on-disk
// cache folder, so every iteration empties the folder and creates a fresh
// backend, neither of them timed (manual time): only preparePipeline() is
// measured. It includes writing the pipeline cache back to the folder, which
// the backend does after each compile.
//
// With `throughFirstDraw` the first draw is timed too: lavapipe (like other
// drivers that compile state-dependent variants) finishes its machine-code
// compile there, tens of milliseconds that preparePipeline() alone misses.
void runCompile(benchmark::State& state, const backends::BackendEntry* entry, backends::BackendOptions options,
                fs::path cacheDir, std::shared_ptr<const BenchFrame> bench, bool throughFirstDraw) {
  try {
    for (auto _ : state) {
      removeContents(cacheDir);
      const std::unique_ptr<backends::Backend> backend = entry->create(options);
      const auto start = std::chrono::steady_clock::now();
      backend->preparePipeline(bench->frame);
      if (throughFirstDraw) backend->draw(bench->frame);
      const auto stop = std::chrono::steady_clock::now();
      state.SetIterationTime(std::chrono::duration<double>(stop - start).count());
    }
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }
  state.counters["lights"] = double(bench->load.keptLights);
}

benchmark::internal::Benchmark* timed(benchmark::internal::Benchmark* b) {
  return b->Unit(benchmark::kMillisecond)
      ->MinTime(kMinTimeSeconds)
      ->Repetitions(kRepetitions)
      ->ReportAggregatesOnly(true);
}

void registerDraws(const std::string& backendName, backends::Backend* backend, const std::string& sceneId,
                   const std::shared_ptr<const BenchFrame>& bench) {
  timed(benchmark::RegisterBenchmark(("BM_Draw/" + backendName + "/" + sceneId).c_str(),
                                     [backend, bench](benchmark::State& st) { runDraw(st, backend, bench, false); }))
      ->UseRealTime();
  timed(benchmark::RegisterBenchmark(("BM_DrawReadback/" + backendName + "/" + sceneId).c_str(),
                                     [backend, bench](benchmark::State& st) { runDraw(st, backend, bench, true); }))
      ->UseRealTime();
}

std::string gridName(const char* prefix, int i, int k) {
  std::string name(prefix);  // appended, not `prefix + ...`: GCC 12 warns falsely (-Wrestrict) on that
  name += std::to_string(i);
  name += '_';
  name += std::to_string(k);
  return name;
}

// 1280x720, seen from straight above (orthographic, exactly the field), so
// every pixel is covered: an 8x8 grid of 1.6 x 0.9 floor tiles with one point
// light 0.4 above the centre of each, and 16 boxes (0.5) on tile corners. With
// range 0.85 a light touches the bounds of its own tile, of the tiles next to
// it (not the diagonal ones) and of the boxes at its tile's corners: each tile
// gets 3-5 lights and each box 4, so per-object lists (at most 8) matter
// against all 64 lights per pixel.
Scene sixtyFourLightsOverAField(bool lightsPerObject) {
  constexpr int kTiles = 8;
  constexpr double kTileX = 1.6, kTileZ = 0.9;
  Scene s;
  s.name = lightsPerObject ? "lights64-1280x720-per-object" : "lights64-1280x720-all";
  s.sourcePath = "render_bench synthetic " + s.name;
  s.image = {1280, 720};
  s.camera = Camera{{0, 10, 0}, {0, 0, 0}, {0, 0, -1}, Projection::Orthographic, 60, kTiles * kTileZ, 0.1, 100};
  s.pipeline.lightsPerObject = lightsPerObject;
  const double x0 = -kTiles * kTileX / 2, z0 = -kTiles * kTileZ / 2;
  for (int i = 0; i < kTiles; ++i) {
    for (int k = 0; k < kTiles; ++k) {
      const double x = x0 + (i + 0.5) * kTileX, z = z0 + (k + 0.5) * kTileZ;
      Object tile;
      tile.name = gridName("tile", i, k);
      tile.mesh.type = MeshType::Plane;
      tile.mesh.planeSizeX = kTileX;
      tile.mesh.planeSizeZ = kTileZ;
      tile.transform.translate = {x, 0, z};
      tile.albedo = {0.8, 0.8, 0.8};
      s.objects.push_back(tile);
      Light l;
      l.name = gridName("p", i, k);
      l.type = LightType::Point;
      l.position = {x, 0.4, z};
      l.range = 0.85;
      l.color = {0.5 + 0.5 * (i % 2), 0.5 + 0.5 * (k % 2), 1.0};
      s.lights.push_back(l);
    }
  }
  for (int i = 1; i < kTiles; i += 2) {
    for (int k = 1; k < kTiles; k += 2) {
      Object box;
      box.name = gridName("box", i, k);
      box.mesh.type = MeshType::Box;
      box.mesh.boxSize = {0.5, 0.5, 0.5};
      box.transform.translate = {x0 + i * kTileX, 0.25, z0 + k * kTileZ};
      box.albedo = {0.9, 0.6, 0.3};
      s.objects.push_back(box);
    }
  }
  return s;
}

void registerSynthetic(const std::string& backendName, backends::Backend* backend) {
  std::vector<std::shared_ptr<const BenchFrame>> benches;
  for (const bool perObject : {false, true}) {
    std::shared_ptr<const BenchFrame> bench;
    try {
      bench = makeBenchFrame(sixtyFourLightsOverAField(perObject));
    } catch (const std::exception& e) {
      std::fprintf(stderr, "render_bench: synthetic scenes not registered: %s\n", e.what());
      return;
    }
    // SPEC 5.1: srp keeps up to 64 other lights; all 64 must be in view and kept.
    const std::size_t kept = bench->frame.selection.packed.other.size();
    if (kept != 64) {
      std::fprintf(stderr, "render_bench: synthetic scene %s keeps %zu point/spot lights, not 64; "
                   "synthetic scenes not registered\n", bench->frame.scene().name.c_str(), kept);
      return;
    }
    benches.push_back(std::move(bench));
  }
  for (const auto& bench : benches) registerDraws(backendName, backend, "synthetic/" + bench->frame.scene().name, bench);
}

void registerSceneFiles(const std::string& backendName, backends::Backend* backend,
                        const backends::BackendEntry* entry, const backends::BackendOptions& options,
                        const fs::path& cacheDir) {
  const fs::path root = fs::path(LIGHTCTS_SOURCE_DIR) / "suite" / "scenes";
  std::vector<fs::path> files;
  std::error_code ec;
  for (const auto& group : fs::directory_iterator(root, ec)) {
    if (!group.is_directory()) continue;
    for (const auto& file : fs::directory_iterator(group.path(), ec))
      if (file.path().extension() == ".json") files.push_back(file.path());
  }
  std::sort(files.begin(), files.end());
  for (const fs::path& file : files) {
    const std::string sceneId = file.parent_path().filename().string() + "/" + file.stem().string();
    std::shared_ptr<const BenchFrame> bench;
    try {
      bench = makeBenchFrame(loadSceneFile(file.string()));
    } catch (const std::exception& e) {
      std::fprintf(stderr, "render_bench: %s not registered: %s\n", sceneId.c_str(), e.what());
      continue;
    }
    registerDraws(backendName, backend, sceneId, bench);
    for (const bool throughFirstDraw : {false, true}) {
      const std::string name = throughFirstDraw ? "BM_CompileAndFirstDraw/" : "BM_PipelineCompile/";
      timed(benchmark::RegisterBenchmark((name + backendName + "/" + sceneId).c_str(),
                                         [entry, options, cacheDir, bench, throughFirstDraw](benchmark::State& st) {
                                           runCompile(st, entry, options, cacheDir, bench, throughFirstDraw);
                                         }))
          ->UseManualTime();
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  // The pipeline-compile benchmarks must measure a real compile, not a hit in
  // the on-disk pipeline cache ($LIGHTCTS_CACHE_DIR, else ~/.cache/lightcts):
  // point the cache at a fresh, empty folder of this process before any
  // backend is created (runCompile empties it again before every iteration),
  // and remove it at the end. This also keeps the user's cache untouched.
  const fs::path cacheDir =
      fs::temp_directory_path() / ("lightcts-render-bench-cache-" + std::to_string(::getpid()));
  fs::remove_all(cacheDir);
  fs::create_directories(cacheDir);
  ::setenv("LIGHTCTS_CACHE_DIR", cacheDir.c_str(), 1);

  // --driver=softpipe (our flag, taken out before Google Benchmark sees the
  // rest) runs the GL backends on softpipe instead of llvmpipe. Mesa loads
  // one driver per process, so each driver needs a run of its own.
  backends::BackendOptions options{};
  std::vector<char*> arguments;
  for (int i = 0; i < argc; ++i) {
    const std::string_view a(argv[i]);
    if (a.starts_with("--driver=")) options.driver = std::string(a.substr(9));
    else arguments.push_back(argv[i]);
  }
  argc = int(arguments.size());
  argv = arguments.data();

  // One backend object per backend, for the draw benchmarks; it lives until
  // every benchmark has run. Validation stays off (BackendOptions default):
  // it would time the layers, not the driver.
  std::vector<std::unique_ptr<backends::Backend>> backendsInUse;
  for (const backends::BackendEntry& entry : backends::compiledBackends()) {
    const bool gl = entry.name != "vulkan";
    // Vulkan has no --driver; with one, only the GL backends run.
    if (!gl && !options.driver.empty()) continue;
    const std::string name =
        gl && !options.driver.empty() && options.driver != "llvmpipe" ? entry.name + "-" + options.driver : entry.name;
    std::unique_ptr<backends::Backend> backend;
    try {
      backend = entry.create(options);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "render_bench: skipping backend %s: %s\n", name.c_str(), e.what());
      continue;
    }
    const backends::DeviceInfo info = backend->device();
    benchmark::AddCustomContext(name + ".device", info.name);
    benchmark::AddCustomContext(name + ".driver", info.driver + " " + info.driverVersion);
    benchmark::AddCustomContext(name + ".api", info.apiVersion);
    registerSynthetic(name, backend.get());
    registerSceneFiles(name, backend.get(), &entry, options, cacheDir);
    backendsInUse.push_back(std::move(backend));
  }

  benchmark::Initialize(&argc, argv);
  int status = 1;
  if (!benchmark::ReportUnrecognizedArguments(argc, argv)) {
    benchmark::RunSpecifiedBenchmarks();
    status = 0;
  }
  benchmark::Shutdown();
  backendsInUse.clear();
  std::error_code ec;
  fs::remove_all(cacheDir, ec);
  return status;
}
