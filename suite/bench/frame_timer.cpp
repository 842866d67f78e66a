#include "suite/bench/frame_timer.h"

#include "results/bench_names.h"
#include "suite/bench/lighting_cost.h"
#include "suite/bench/time_source.h"
#include "suite/bench/wall_clock.h"

#include <cstdio>
#include <exception>
#include <memory>
#include <optional>
#include <utility>

namespace bench {
namespace {

void setLoadCounters(benchmark::State& state, const RunState& run, const FrameLoad& load, bool specularLobe) {
  auto& c = state.counters;
  const double iterations = double(state.iterations());
  c[std::string(results::bench::kPixels)] = load.pixels;
  c[std::string(results::bench::kTriangles)] = load.triangles;
  c[std::string(results::bench::kLights)] = double(load.keptLights);
  c[std::string(results::bench::kLightsPerPixel)] = load.lightsPerPixel;
  c[std::string(results::bench::kPixelsPerS)] = benchmark::Counter(load.pixels * iterations, benchmark::Counter::kIsRate);
  c[std::string(results::bench::kPixelLightEvalsPerS)] =
      benchmark::Counter(load.pixels * load.lightsPerPixel * iterations, benchmark::Counter::kIsRate);
  if (run.settings.peakGflops && run.flopsPerPixelLight > 0) {
    // A frame with srp materials evaluates the lobe per light too (counted
    // as if every pixel had it: the field's specular modes are srp throughout).
    const double flops = run.flopsPerPixelLight + (specularLobe ? flopsOfSpecularLobe() : 0.0);
    c[std::string(results::bench::kFlopsPerPixelLight)] = flops;
    c[std::string(results::bench::kLimitMs)] = load.pixels * load.lightsPerPixel * flops / (*run.settings.peakGflops * 1e9) * 1e3;
  }
}

void setErrorCounters(benchmark::State& state, const ImageError& e) {
  auto& c = state.counters;
  c[std::string(results::bench::kErrRmse)] = e.rmse;
  c[std::string(results::bench::kErrMaxAbs)] = e.maxAbs;
  c[std::string(results::bench::kErrPsnrDb)] = e.psnrDb;
  c[std::string(results::bench::kErrPerceptualFail)] = e.perceptualFail;
  // NaN or infinite pixels: the mode is broken; err_max_abs is infinite and
  // err_rmse, err_psnr_db NaN, which the JSON writes as null.
  c[std::string(results::bench::kErrNonfinitePixels)] = double(e.nonFinitePixels);
}

void setBakeCounters(benchmark::State& state, const BenchFrame& bench) {
  const BakeTime& bake = *bench.spec.bake;
  const double resolution = double(bench.frame.scene().objects.front().lightmapResolution);
  auto& c = state.counters;
  c[std::string(results::bench::kBakeMs)] = bake.medianMs;
  c[std::string(results::bench::kBakeRuns)] = double(bake.runs);
  c[std::string(results::bench::kLightmapTexels)] = resolution * resolution;
}

}  // namespace

void timeFrame(benchmark::State& state, RunState& run, const BenchFrame& bench, bool withReadback) {
  try {
    backends::Backend& backend = run.backendFor(bench);
    const bool withError = !bench.spec.referenceKey.empty();
    backend.preparePipeline(bench.frame);
    // Repetitions call this again: the warm-up draw is needed only when
    // another frame was drawn on this backend since; --quick times nothing
    // worth warming up for.
    if (!run.slow() && !run.settings.quick && run.lastDrawn[&backend] != &bench) backend.draw(bench.frame);
    run.lastDrawn[&backend] = &bench;
    double wallMs = 0, deviceMs = 0, shadowMs = 0;
    bool deviceEveryTime = true, shadowEveryTime = bench.frame.shadows.any();
    int flagged = 0;                // iterations whose device time the wall time rules out
    double flaggedDevice = 0, flaggedWall = 0;  // the first of them, for the label
    imaging::Image image;  // frame_readback: the last one read back
    for (auto _ : state) {
      const auto start = Clock::now();
      backend.draw(bench.frame);
      const std::optional<double> device = backend.lastDrawDeviceMilliseconds();
      // SPEC 3.9: the shadow passes' share of the draw, timed apart.
      if (const std::optional<double> shadow = backend.lastShadowPassDeviceMilliseconds()) shadowMs += *shadow;
      else shadowEveryTime = false;
      if (withReadback) {
        image = backend.readback();
        benchmark::DoNotOptimize(image.pixels.data());
      }
      const double wall = millisecondsSince(start);
      wallMs += wall;
      if (device) deviceMs += *device;
      else deviceEveryTime = false;
      // The device's time when it is the run's source and can be right
      // (time_source.h); otherwise, and for the rest of this benchmark
      // once one iteration's could not, the wall time.
      bool useDevice = run.deviceTime && device && !withReadback && !run.wallTimeOnly.contains(&bench);
      if (useDevice && !deviceTimeIsPlausible(*device, wall)) {
        if (flagged++ == 0) flaggedDevice = *device, flaggedWall = wall;
        run.wallTimeOnly.insert(&bench);
        useDevice = false;
      }
      state.SetIterationTime((useDevice ? *device : wall) / 1e3);
    }
    auto& c = state.counters;
    c[std::string(results::bench::kWallMs)] = benchmark::Counter(wallMs, benchmark::Counter::kAvgIterations);
    if (deviceEveryTime && state.iterations() > 0)
      c[std::string(results::bench::kDeviceMs)] = benchmark::Counter(deviceMs, benchmark::Counter::kAvgIterations);
    if (shadowEveryTime && state.iterations() > 0)
      c[std::string(results::bench::kShadowPassMs)] = benchmark::Counter(shadowMs, benchmark::Counter::kAvgIterations);
    setLoadCounters(state, run, bench.load, bench.frame.features.specularBrdf);
    if (flagged > 0 || run.wallTimeOnly.contains(&bench)) {
      c[std::string(results::bench::kDeviceTimeFlagged)] = double(flagged);
      char label[200];
      std::snprintf(label, sizeof label,
                    flagged > 0 ? "wall time: device time %.3g ms below half the wall time %.3g ms (a timer that missed work, or a stall outside its interval)"
                                : "wall time: an earlier repetition's device time was below half its wall time",
                    flaggedDevice, flaggedWall);
      state.SetLabel(label);
    }
    // One readback per draw: frame_readback's last image when it has one.
    // The error (and its ideal, when it is not known yet) after the timed
    // loop: untimed, and before the next benchmark starts.
    const auto lastImage = [&] { return image.pixels.empty() ? backend.readback() : std::move(image); };
    if (withError) setErrorCounters(state, run.errorFor(bench, lastImage));
    if (bench.spec.bake) setBakeCounters(state, bench);
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
  }
}

void timePipeline(benchmark::State& state, RunState& run, const BenchFrame& bench) {
  try {
    backends::BackendOptions options = run.options;
    options.variant.specialised = !bench.spec.fullShader;
    for (auto _ : state) {
      emptyPipelineCache(run);
      const std::unique_ptr<backends::Backend> backend = run.entry->create(options);
      const auto start = Clock::now();
      backend->preparePipeline(bench.frame);
      state.SetIterationTime(millisecondsSince(start) / 1e3);
    }
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }
  state.counters[std::string(results::bench::kLights)] = double(bench.load.keptLights);
}

namespace {

// `frame` drawn from a fresh copy of its prepared scene (the cookie images
// are shared, not copied: they are what the backend uploads).
lighting::Frame withFreshScene(const lighting::Frame& frame) {
  lighting::Frame fresh = frame;
  fresh.prepared = std::make_shared<lighting::PreparedScene>(*frame.prepared);
  return fresh;
}

double cookieTexels(const lighting::Frame& frame) {
  double texels = 0;
  for (const auto* lights : {&frame.cookies.textureLights, &frame.cookies.cubeLights})
    for (const int l : *lights)
      for (const auto& image : frame.scene().lights[std::size_t(l)].cookie->images)
        texels += double(image->width) * image->height;
  return texels;
}

}  // namespace

void timeUpload(benchmark::State& state, RunState& run, const lighting::Frame& frame) {
  backends::Backend& backend = *run.specialised;
  try {
    lighting::Frame current = withFreshScene(frame);
    backend.prepareTextures(current);
    for (auto _ : state) {
      // The previous copy lives until the new one is made: never at its address.
      lighting::Frame next = withFreshScene(frame);
      const auto start = Clock::now();
      backend.prepareTextures(next);
      state.SetIterationTime(millisecondsSince(start) / 1e3);
      current = std::move(next);
    }
  } catch (const std::exception& e) {
    run.lastDrawn.erase(&backend);
    state.SkipWithError(e.what());
    return;
  }
  run.lastDrawn.erase(&backend);  // its textures are no benchmark frame's now
  const double texels = cookieTexels(frame);
  auto& c = state.counters;
  c["cookie_textures"] = double(frame.cookies.textureLights.size());
  c["cookie_cubes"] = double(frame.cookies.cubeLights.size());
  c["cookie_texels"] = texels;
  c["texels_per_s"] = benchmark::Counter(texels, benchmark::Counter::kIsIterationInvariantRate);
}

}  // namespace bench
