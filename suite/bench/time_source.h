// Whether the device's own time can be the benchmarks' time. On llvmpipe,
// GL's GL_TIME_ELAPSED covers only part of the work (about a tenth of a frame
// that glFinish waits for), while Vulkan's timestamps on lavapipe match the
// wall-clock time of the draw. So three untimed draws of a small field on the
// shipped-shader backend, and the device's time is used when the last one
// reports at least half the wall-clock time.
#pragma once

#include "suite/bench/run_state.h"

#include <string>

namespace bench {

// Sets run.deviceTime; returns the line for the JSON context
// (`frame_bench.time`). Throws what the draw throws.
std::string calibrateTimeSource(RunState& run);

}  // namespace bench
