#include "suite/bench/driver_speed.h"

#include "baking/bake.h"
#include "suite/bench/bench_scenes.h"
#include "suite/bench/run_state.h"
#include "suite/bench/wall_clock.h"

#include <cstdio>

namespace bench {

std::string chooseFrameSet(RunState& run) {
  using FrameSet = Settings::FrameSet;
  if (run.settings.frameSet != FrameSet::Measured) {
    run.slowDriver = run.settings.frameSet == FrameSet::Scaled;
    return run.slowDriver ? "scaled down (--set=scaled)" : "full (--set=full)";
  }
  FieldSpec field;
  field.width = kProbeWidth;
  field.height = kProbeHeight;
  BenchFrameSpec spec;
  spec.prepared = baking::prepareBakedScene(fieldScene(field, "driver-speed"));
  const auto bench = makeBenchFrame(std::move(spec));
  backends::Backend& backend = *run.specialised;
  // The first draw also compiles the pipeline and fills the caches, so it is
  // the slowest: under the limit, the driver is fast enough; over it, the
  // second draw decides.
  double probeMs = 0;
  for (int i = 0; i < 2; ++i) {
    const auto start = Clock::now();
    backend.draw(bench->frame);
    probeMs = millisecondsSince(start);
    if (!runsScaledDownSet(probeMs)) break;
  }
  const double estimateMs = fullSizeEstimateMs(probeMs);
  run.slowDriver = runsScaledDownSet(probeMs);
  char text[200];
  std::snprintf(text, sizeof text, "%s (probe %.3g ms at %dx%d, about %.3g ms at 1280x720; limit %.0f ms)",
                run.slowDriver ? "scaled down" : "full", probeMs, kProbeWidth, kProbeHeight, estimateMs,
                kFullSetFrameLimitMs);
  return text;
}

}  // namespace bench
