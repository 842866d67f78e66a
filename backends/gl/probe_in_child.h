// Runs a probe (create a context, read its strings) in a forked child and
// returns what it found. Mesa loads one driver per process, so listing
// llvmpipe and softpipe side by side needs a process each; a probe that
// crashes the child costs only that line of the listing.
#pragma once

#include "backends/backend.h"

#include <functional>
#include <optional>
#include <string>

namespace backends::gl {

struct ProbeResult {
  std::optional<DeviceInfo> device;
  std::string error;  // why there is none
};

ProbeResult probeInChild(const std::function<DeviceInfo()>& probe);

}  // namespace backends::gl
