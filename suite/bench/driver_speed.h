// Which set a combination's frame process runs, decided by how fast its
// driver draws, not by its name: before anything is registered, the 64-light
// field (the all-lights mode, shipped shaders) is drawn at 320x180, a
// sixteenth of the full set's 1280x720 pixels: the first draw (which also
// compiles the pipeline) decides when it is under the limit, else the
// second. A driver whose probe, scaled to
// 1280x720 (times 16: the field's cost is per pixel-light), exceeds
// kFullSetFrameLimitMs would take longer than the full bench's budget
// allows over the full set's frame medians, and runs the scaled-down set:
// the fields at 160x90, no cost curves (docs/bench-format.md, "What runs").
// `--set=full` or `--set=scaled` forces a set (`lightcts bench --full-set`).
#pragma once

#include <string>

namespace bench {

struct RunState;

inline constexpr double kFullSetFrameLimitMs = 1000;
inline constexpr int kProbeWidth = 320, kProbeHeight = 180;

// The probe's time scaled to a 1280x720 field frame.
constexpr double fullSizeEstimateMs(double probeMs) {
  return probeMs * (1280.0 * 720.0) / (double(kProbeWidth) * kProbeHeight);
}
// The rule: the scaled-down set when that estimate is over the limit.
constexpr bool runsScaledDownSet(double probeMs) { return fullSizeEstimateMs(probeMs) > kFullSetFrameLimitMs; }

// Sets run.slowDriver and returns the context line `frame_bench.set` says
// (the probe's time, the estimate and the set), e.g. "full (probe 6.1 ms at
// 320x180, about 98 ms at 1280x720; limit 1000 ms)".
std::string chooseFrameSet(RunState& run);

}  // namespace bench
