// The frame benchmarks' own flags (frame_benchmarks.h lists them): read from
// the command line and checked against SPEC 8's backend names and the one
// table of backend combinations (backends/backend_combinations.h), before
// anything else runs. Every other argument is Google Benchmark's.
#pragma once

#include "backends/backend_combinations.h"
#include "lighting/light_clusters.h"
#include "shaders/shader_variant.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace bench {

// Which time the frame benchmarks report: the device's when a calibration
// frame shows it covers the work (time_source.h), or as --time_source says
// (`device` is for tests that need a device timer known to miss work).
enum class TimeSource { Calibrated, Device, Wall };

struct Settings {
  std::string backend = "vulkan";
  std::string driver;  // as given; empty: the backend's default (llvmpipe for GL)
  std::optional<double> peakGflops;
  bool quick = false;
  bool suiteScenes = false;
  TimeSource timeSource = TimeSource::Calibrated;  // --time_source=auto|device|wall
  // --set=auto|full|scaled: which set the combination runs. auto, the
  // default, decides by the driver's measured speed (driver_speed.h); full
  // and scaled force one.
  enum class FrameSet { Measured, Full, Scaled } frameSet = FrameSet::Measured;
  std::filesystem::path scenes;  // --scenes; the caller's default when not given
  // --ideal_cache=DIR: the ideal references, untimed and the same for every
  // combination, read from DIR when an earlier process of the run left them
  // there, else rendered and left there (`lightcts bench` passes raw/ideal).
  std::filesystem::path idealCache;
  // --error_cache=DIR: the err_* counters kept across runs,
  // under DIR/<fingerprint of the code they depend on>, each file named by
  // the ideal's key and an XXH3-128 of the read-back image, so a later run
  // whose frame is bit for bit the same reads its error instead of running
  // compare_Yee, and renders no ideal for it. Empty: the errors are kept
  // beside the ideals (this run's alone). Ignored with --suite_scenes: a
  // suite scene's key is its name, not its content.
  std::filesystem::path errorCache;
  // --mutant (tests only): every backend draws this deliberately wrong
  // variant (shaders/shader_variant.h), so a test can time a broken mode.
  shaders::Mutant mutant = shaders::Mutant::None;
  // --uniform_reads=constant (a driver probe): the shaders read the uniforms
  // that steer loops and branches at constant offsets, which lavapipe 22.3
  // inlines and recompiles for (docs/vendors.md); opaque, the default, is
  // the shipped shaders'.
  bool constantUniformReads = false;
  // --cluster_tile=N, --cluster_slices=N: the clustered mode's grid on
  // the fields and the light curve; the tile curve varies the tile.
  lighting::ClusterGridSpec clusterGrid;
  // --field_size=WxH (tests only): the 64-light field at this size instead
  // of the set's own (fieldSize), so a smoke test of a full-set mode draws
  // and measures a small frame. Zero: the set's own.
  int fieldWidth = 0, fieldHeight = 0;
  // The combination backend and driver select: its suffix names every
  // benchmark.
  const backends::BackendCombination* combination = nullptr;
};

struct ParsedFlags {
  Settings settings;
  std::vector<char*> rest;  // argv[0] and what Google Benchmark reads, in order
  int usageError = 0;       // 0, or the exit status of a bad flag (the message is on stderr)
};

ParsedFlags parseFlags(int argc, char** argv, const std::filesystem::path& defaultScenes);

}  // namespace bench
