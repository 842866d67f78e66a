// The frame benchmarks of one backend combination (SPEC 9): the
// program's steps, each done by its own file. Names and counters:
// docs/bench-format.md. What runs:
//   frame/<b>/lights64-1280x720/<mode>           mode: all-lights, per-object, legacy-4+4, and each
//                                                with the full shader (full-shader = all-lights);
//                                                the srp-brdf modes; cookie-lights and cookies
//                                                (cookies off and on); deferred-hdr32, -hdr16, -ldr8
//   frame_readback/<b>/lights64-1280x720/<mode>  the light-path modes: all-lights, per-object, legacy-4+4, deferred-*
//   pipeline/<b>/lights64-1280x720/<mode>         preparePipeline with an empty cache
//   upload/<b>/lights64-1280x720/cookies/<n>      prepareTextures of a fresh copy of the cookie
//                                                field, n x n cookies: n = 64, 256, 1024 (--quick: 256)
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
// frame_readback times the light-path modes only (all-lights, per-object,
// legacy-4+4, clustered, deferred-*): a readback's cost does not depend on
// the mode. A second context path to a driver (gl-osmesa beside gl-egl,
// gl-egl-zink beside vulkan) runs the field's light-path modes and the
// all-lights pipeline only. A slow driver, by its measured speed
// (driver_speed.h: a 1280x720 field frame estimated over a second), runs a
// scaled-down set: the fields at 160x90, `frame` only, one iteration times
// 3 repetitions, no cost curves; `--set=full` runs the full set anyway.
//
// The steps: flags (bench_settings), the run's state and its pipeline cache
// folder (run_state), the backend, the JSON context and the time source
// (time_source), the families (bench_families.h) registered through
// the Registrar, then Google Benchmark with the plain-name reporters
// (bench_reporters).
#include "suite/bench/frame_benchmarks.h"

#include "app/exit_status.h"

#include "suite/bench/bench_families.h"
#include "suite/bench/bench_registrar.h"
#include "suite/bench/bench_reporters.h"
#include "suite/bench/bench_settings.h"
#include "suite/bench/driver_speed.h"
#include "suite/bench/error_prepass.h"
#include "suite/bench/lighting_cost.h"
#include "suite/bench/run_state.h"
#include "suite/bench/time_source.h"

#include <benchmark/benchmark.h>

#include <cstdio>
#include <exception>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

namespace bench {
namespace {

// render_bench exits as the lightcts command does (SPEC 8).
using app::kExitBadInput, app::kExitInternalError, app::kExitNotSupported, app::kExitSuccess;

void addDeviceContext(const RunState& run) {
  const backends::DeviceInfo info = run.specialised->device();
  benchmark::AddCustomContext("backend", run.suffix());
  benchmark::AddCustomContext(run.suffix() + ".device", info.name);
  benchmark::AddCustomContext(run.suffix() + ".driver", info.driver);
  benchmark::AddCustomContext(run.suffix() + ".driver_version", info.driverVersion);
  benchmark::AddCustomContext(run.suffix() + ".api", info.apiVersion);
}

// Google Benchmark runs them in this order: every benchmark of the
// shipped-shader backend first, then full-shader (its backend is created on
// first use, by the error prepass when it runs), then pipeline (a fresh
// backend per iteration; a GL backend makes its context current on every
// call, so none of them depends on what another left current). The cookie uploads use the shipped-shader backend
// too: last of its benchmarks.
// Returns the frames whose errors the prepass may compute.
std::vector<ErrorCandidate> registerAll(const std::shared_ptr<RunState>& run) {
  Registrar registrar(run);
  const FieldModes field = fieldModes(*run);
  registerFieldModes(registrar, field.shipped);
  if (run->secondContextPath()) {
    // The driver's features and curves are timed on its first path (gl-egl,
    // gl-egl-softpipe, vulkan for zink's lavapipe); this path adds its
    // light-path frames and a pipeline.
    registerFieldPipelines(registrar, field.pipeline);
    return registrar.errorCandidates();
  }
  registerDenseFieldModes(registrar, denseFieldModes(*run));
  registerMeshFieldModes(registrar, meshFieldModes(*run));
  registerLightmapModes(registrar);
  registerCurves(registrar);
  if (run->settings.suiteScenes) registerSuiteScenes(registrar);
  registerCookieUploads(registrar);  // the shipped-shader backend's last: the draws after it warm up again
  registerFieldModes(registrar, field.full);
  registerFieldPipelines(registrar, field.pipeline);
  return registrar.errorCandidates();
}

// Google Benchmark reads `arguments` (argv[0] first) and runs what is
// registered; `beforeRun` once the flags are read (the filter is known).
int runRegistered(std::vector<char*> arguments, const std::function<void()>& beforeRun) {
  const std::vector<std::string_view> flags(arguments.begin() + 1, arguments.end());
  const Reporters reporters = plainNameReporters(flags);
  int count = int(arguments.size());
  arguments.push_back(nullptr);
  benchmark::Initialize(&count, arguments.data());
  int status = kExitBadInput;
  if (!benchmark::ReportUnrecognizedArguments(count, arguments.data())) {
    beforeRun();
    benchmark::RunSpecifiedBenchmarks(reporters.display.get(), reporters.file.get());
    status = kExitSuccess;
  }
  benchmark::Shutdown();
  return status;
}

}  // namespace

int runFrameBenchmarks(int argc, char** argv) {
  ParsedFlags flags = parseFlags(argc, argv, std::filesystem::path(LIGHTCTS_SOURCE_DIR) / "suite" / "scenes");
  if (flags.usageError) return flags.usageError;
  auto run = std::make_shared<RunState>();
  run->settings = flags.settings;
  if (!run->settings.combination->driver.empty())  // a backend with a driver choice (GL): the driver asked for
    run->options.driver = run->settings.driver;
  run->options.variant.mutant = run->settings.mutant;  // None unless a test asks
  run->options.variant.opaqueUniformReads = !run->settings.constantUniformReads;  // a driver probe when off
  run->flopsPerPixelLight = flopsPerPixelLight();

  run->entry = backends::findBuiltBackendEntry(run->settings.backend);
  if (!run->entry) {
    std::fprintf(stderr, "render_bench: %s: not compiled into this build (NotSupported)\n", run->suffix().c_str());
    return kExitNotSupported;
  }

  useFreshPipelineCache(*run);
  const std::filesystem::path cacheDir = run->cacheDir;
  auto cleanUp = [&] {
    benchmark::ClearRegisteredBenchmarks();
    run.reset();  // the backends go before their cache folder
    std::error_code ec;
    std::filesystem::remove_all(cacheDir, ec);
  };

  // Validation stays off (BackendOptions default): it would time the layers, not the driver.
  try {
    run->specialised = run->entry->create(run->options);
  } catch (const backends::NotSupportedError& e) {
    std::fprintf(stderr, "render_bench: %s: %s (NotSupported)\n", run->suffix().c_str(), e.what());
    cleanUp();
    return kExitNotSupported;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "render_bench: %s: %s\n", run->suffix().c_str(), e.what());
    cleanUp();
    return kExitInternalError;
  }
  addDeviceContext(*run);
  try {
    // The set first: the calibration frame's size and every family depend on it.
    const std::string set = chooseFrameSet(*run) + (run->settings.quick ? ", quick" : "");
    std::fprintf(stderr, "render_bench: %s: the %s set\n", run->suffix().c_str(), set.c_str());
    benchmark::AddCustomContext("frame_bench.set", set);
    benchmark::AddCustomContext("frame_bench.time", calibrateTimeSource(*run));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "render_bench: %s: the speed probe or calibration draw failed: %s\n", run->suffix().c_str(),
                 e.what());
    cleanUp();
    return kExitInternalError;
  }
  benchmark::AddCustomContext("frame_bench.error",
                              "against the --ideal reference over its compared pixels; PSNR peak = max of the "
                              "ideal RGB; perceptual: compare_Yee, 100 cd/m2, 45 deg field of view");
  if (run->settings.mutant != shaders::Mutant::None)
    benchmark::AddCustomContext("frame_bench.mutant", std::string(shaders::mutantName(run->settings.mutant)));
  if (run->settings.constantUniformReads)
    benchmark::AddCustomContext("frame_bench.uniform_reads",
                                "constant (a driver probe: steering uniforms at constant offsets, docs/vendors.md)");
  if (run->settings.peakGflops)
    benchmark::AddCustomContext("frame_bench.peak_gflops", std::to_string(*run->settings.peakGflops));

  std::vector<ErrorCandidate> errorCandidates;
  try {
    errorCandidates = registerAll(run);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "render_bench: preparing the benchmark scenes failed: %s\n", e.what());
    cleanUp();
    return kExitInternalError;
  }
  // The errors first, on every core, untimed (suite/bench/error_prepass.h).
  const int status = runRegistered(std::move(flags.rest),
                                   [&] { precomputeErrors(*run, errorCandidates, benchmark::GetBenchmarkFilter()); });
  cleanUp();
  return status;
}

}  // namespace bench
