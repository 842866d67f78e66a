#include "suite/bench/time_source.h"

#include "baking/bake.h"
#include "suite/bench/bench_scenes.h"
#include "suite/bench/wall_clock.h"

#include <cstdio>
#include <optional>

namespace bench {

std::string calibrateTimeSource(RunState& run) {
  if (run.settings.timeSource != TimeSource::Calibrated) {
    run.deviceTime = run.settings.timeSource == TimeSource::Device;
    return run.deviceTime ? "device (--time_source=device: not calibrated; implausible device times are still flagged)"
                          : "wall (--time_source=wall)";
  }
  FieldSpec field;
  // Small on a slow driver and with --quick (a smoke run: only that it works).
  const bool small = run.slow() || run.settings.quick;
  field.width = small ? 128 : 640;
  field.height = small ? 72 : 360;
  BenchFrameSpec spec;
  spec.prepared = baking::prepareBakedScene(fieldScene(field, "time-calibration"));
  const auto bench = makeBenchFrame(std::move(spec));
  backends::Backend& backend = *run.specialised;
  std::optional<double> device;
  double wall = 0;
  for (int i = 0; i < 3; ++i) {
    const auto start = Clock::now();
    backend.draw(bench->frame);
    device = backend.lastDrawDeviceMilliseconds();
    wall = millisecondsSince(start);
  }
  run.deviceTime = device && *device >= 0.5 * wall;
  char text[320];
  if (!device)
    std::snprintf(text, sizeof text, "wall: the device reports no time of its own");
  else if (run.deviceTime)
    std::snprintf(text, sizeof text,
                  "device (frame kind): %.3g ms of device time for %.3g ms wall on a %dx%d calibration frame", *device,
                  wall, field.width, field.height);
  else
    std::snprintf(text, sizeof text,
                  "wall: the device's time misses most of the work (%.3g ms for %.3g ms wall on a %dx%d calibration "
                  "frame); device_ms is reported beside",
                  *device, wall, field.width, field.height);
  return text;
}

}  // namespace bench
