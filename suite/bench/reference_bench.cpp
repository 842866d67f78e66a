// Speed of the double-precision reference (SPEC 6), with Google Benchmark:
// every scene of suite/scenes, plus two synthetic loads
// (512x512 over 100k triangles; 64 lights summed per pixel). Counters report
// pixels and pixel-light evaluations per second, tolerance shading included.
#include "app/exit_status.h"
#include "baking/bake.h"
#include "lighting/frame.h"
#include "reference/reference_renderer.h"
#include "results/bench_names.h"
#include "scene_input/scene_loader.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <filesystem>
#include <string>

namespace {

using namespace lighting;

void renderFrame(benchmark::State& state, const Scene& scene) {
  auto prepared = baking::prepareBakedScene(scene);  // the suite's baked scenes need their maps
  const Frame frame = prepareFrame(prepared, 0);
  const reference::ReferenceRenderer renderer(prepared);
  std::int64_t evaluations = 0;
  for (auto _ : state) {
    const reference::ReferenceImages images = renderer.render(frame);
    evaluations += images.lightEvaluations;
    benchmark::DoNotOptimize(images.value.pixels.data());
  }
  const double pixels = double(scene.image.width) * scene.image.height;
  state.counters[std::string(results::bench::kPixelsPerS)] = benchmark::Counter(pixels * state.iterations(), benchmark::Counter::kIsRate);
  state.counters[std::string(results::bench::kPixelLightEvalsPerS)] = benchmark::Counter(double(evaluations), benchmark::Counter::kIsRate);
  state.counters[std::string(results::bench::kTriangles)] = double(renderer.triangleCount());
}

Scene sphereOfTriangles(int width, int height, int targetTriangles) {
  Scene s;
  s.image = {width, height};
  s.camera = Camera{{0, 0, 4}, {0, 0, 0}, {0, 1, 0}, Projection::Perspective, 50, 10, 0.1, 100};
  Object sphere;
  sphere.mesh.type = MeshType::Sphere;
  sphere.mesh.sphereRadius = 1.2;
  // segments * (2 * rings - 2) triangles with rings = segments / 2: about segments^2.
  sphere.mesh.sphereSegments = int(std::sqrt(double(targetTriangles)));
  sphere.mesh.sphereRings = sphere.mesh.sphereSegments / 2;
  s.objects.push_back(sphere);
  for (int k = 0; k < 8; ++k) {
    Light l;
    l.type = LightType::Point;
    l.position = {std::cos(k * 0.785) * 2.0, std::sin(k * 0.785) * 2.0, 1.5};
    l.range = 4;
    s.lights.push_back(l);
  }
  return s;
}

Scene sixtyFourLightsOnAPlane(int width, int height) {
  Scene s;
  s.image = {width, height};
  Object floor;
  floor.mesh.subdivisions = 8;
  s.objects.push_back(floor);
  for (int k = 0; k < 64; ++k) {
    Light l;
    l.type = k % 2 ? LightType::Point : LightType::Spot;
    l.position = {-4.0 + (k % 8) * 1.1, 1.0, -4.0 + (k / 8) * 1.1};
    l.range = 20;  // every light reaches every pixel
    l.spotAngleDeg = 170;
    s.lights.push_back(l);
  }
  return s;
}

void registerSceneFiles() {
  namespace fs = std::filesystem;
  const fs::path root = fs::path(LIGHTCTS_SOURCE_DIR) / "suite" / "scenes";
  if (!fs::exists(root)) return;
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    if (entry.path().extension() != ".json") continue;
    const Scene scene = scene_input::loadSceneFile(entry.path().string());
    const std::string name = "reference/" + entry.path().parent_path().filename().string() + "." + scene.name;
    benchmark::RegisterBenchmark(name.c_str(), [scene](benchmark::State& st) { renderFrame(st, scene); })
        ->Unit(benchmark::kMillisecond);
  }
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::RegisterBenchmark("reference/synthetic.sphere-100k-triangles-512x512",
                               [](benchmark::State& st) { renderFrame(st, sphereOfTriangles(512, 512, 100000)); })
      ->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("reference/synthetic.plane-64-lights-256x256",
                               [](benchmark::State& st) { renderFrame(st, sixtyFourLightsOnAPlane(256, 256)); })
      ->Unit(benchmark::kMillisecond);
  registerSceneFiles();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return app::kExitBadInput;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
