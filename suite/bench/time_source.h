// Whether the device's own time can be the benchmarks' time. On llvmpipe,
// GL's GL_TIME_ELAPSED covers an unpredictable part of the work glFinish
// waits for (14 us of a 43 ms one-light frame, 7.8 of 14.3 ms with 64
// lights, on the same 192x192 field), while Vulkan's timestamps on lavapipe match the
// wall-clock time of the draw. So three untimed draws of a small field on the
// shipped-shader backend, and the device's time is used when the last one
// reports at least half the wall-clock time.
#pragma once

#include "suite/bench/run_state.h"

#include <string>

namespace bench {

// Sets run.deviceTime (or takes --time_source=device|wall as given); returns
// the line for the JSON context (`frame_bench.time`). Throws what the draw
// throws.
std::string calibrateTimeSource(RunState& run);

// Whether a draw's device time can be right beside its wall time. Every
// driver the benchmarks run on is synchronous and software (lavapipe,
// llvmpipe, softpipe): Backend::draw returns when the device has finished,
// so the draw's wall interval holds the device's interval and around it the
// CPU's own part (recording, submitting, waking from the wait, reading the
// timer back). The device time can fall short of the wall time only by that
// part: measured 0.9-1.3 ms beside 74-1702 ms of device time on lavapipe's
// mesh field, and on every frame the bench times far less than the device's
// own work. The rule keeps a margin of two: a device time below half the
// wall time would need the CPU's part to outweigh the device's, which no
// timed frame has, so it is a timer that missed work (llvmpipe's
// GL_TIME_ELAPSED, which covers only part of a frame, or a loaded machine's
// stall) and never a point on a plot. Such an iteration takes its
// wall time instead, which is never too low: frame_timer.cpp counts them
// (`device_time_flagged`) and labels the entry.
inline constexpr double kLeastDeviceShareOfWall = 0.5;
inline bool deviceTimeIsPlausible(double deviceMs, double wallMs) { return deviceMs >= kLeastDeviceShareOfWall * wallMs; }

}  // namespace bench
