// Everything one frame-benchmark process shares between its benchmarks: the
// combination and its backends, the on-disk pipeline cache folder, and the
// ideal references and image errors computed so far (each once per key).
#pragma once

#include "backends/backend.h"
#include "imaging/image.h"
#include "suite/bench/bench_frame.h"
#include "suite/bench/bench_settings.h"
#include "suite/bench/image_error.h"

#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>

namespace bench {

struct RunState {
  Settings settings;
  const backends::BackendEntry* entry = nullptr;
  backends::BackendOptions options;
  std::filesystem::path cacheDir;
  double flopsPerPixelLight = 0;  // 0: unknown, no limit counters
  std::unique_ptr<backends::Backend> specialised;  // the shipped shaders
  std::unique_ptr<backends::Backend> full;         // full-shader, made on first use
  std::map<std::string, imaging::Image> ideal;
  std::map<std::string, ImageError> errors;
  std::map<const backends::Backend*, const BenchFrame*> lastDrawn;  // what each backend drew last
  bool deviceTime = false;  // the benchmarks' time is the device's (calibrateTimeSource)
  // Benchmarks one of whose iterations had a device time its wall time rules
  // out (deviceTimeIsPlausible): every later iteration and repetition of
  // them is timed by the wall clock.
  std::set<const BenchFrame*> wallTimeOnly;

  // The combination's suffix (vulkan, gl-egl, gl-osmesa-softpipe, ...): part of every name.
  const std::string& suffix() const { return settings.combination->suffix; }
  // A slow driver, by its measured speed (driver_speed.h): the scaled-down set.
  bool slow() const { return slowDriver; }
  bool slowDriver = false;
  bool secondContextPath() const { return settings.combination->isSecondContextPath(); }

  // The backend object shared by every draw benchmark of its shader variant.
  backends::Backend& backendFor(const BenchFrame& bench);
  // The `--ideal` reference of SPEC 6, rendered once per key in this process.
  const imaging::Image& idealFor(const BenchFrame& bench);
  // The error of `bench` against its ideal reference, computed from
  // `readback()` the first time its key is asked for.
  const ImageError& errorFor(const BenchFrame& bench, const std::function<imaging::Image()>& readback);

  // Frames that read back bit for bit the same have the same error (the
  // full-shader modes and their specialised ones, per-object and all-lights
  // on the field, gl-osmesa and gl-egl): errors are also kept by content, the
  // ideal's key and an XXH3-128 of the image, in memory and as a file: under
  // --error_cache (every run's, by the sources' fingerprint), else beside the
  // ideal cache's (this run's frame processes'), so compare_Yee runs once per
  // distinct image and an ideal is rendered only for an error not known yet.
  static std::string contentKey(const std::string& referenceKey, const imaging::Image& image);
  std::optional<ImageError> errorByContent(const std::string& contentKey) const;
  void keepErrorByContent(const std::string& contentKey, const ImageError& error);
  std::map<std::string, ImageError> errorsByContent;
};

// The pipeline benchmarks must measure a real compile, not a hit in the
// on-disk pipeline cache ($LIGHTCTS_CACHE_DIR, else ~/.cache/lightcts): this
// points the cache at a fresh, empty folder of this process (run.cacheDir)
// before any backend is created; runPipeline empties it again before every
// iteration. The user's cache stays untouched.
void useFreshPipelineCache(RunState& run);
// Empties the folder (between pipeline iterations).
void emptyPipelineCache(const RunState& run);

}  // namespace bench
