// Runs a probe (create a context, read its strings) in a child process and
// returns what it found. Mesa loads one driver per process, so listing
// llvmpipe and softpipe side by side needs a process each; a probe that
// crashes the child costs only that line of the listing.
//
// The child is this program again (/proc/self/exe, as the runner's workers
// are), started as `lightcts probe-driver --backend B --driver D` in its own
// process group, with a deadline: LIGHTCTS_PROBE_TIMEOUT_S seconds (default
// 30). A probe that does not answer in time (a hung driver) has its whole
// process group killed and is a Timeout, so `lightcts backends` never hangs.
// Only the `lightcts` binary answers `probe-driver` (app/main.cpp).
#pragma once

#include "backends/backend.h"

#include <functional>
#include <optional>
#include <string>

namespace backends::gl {

struct ProbeResult {
  std::optional<DeviceInfo> device;
  std::string error;      // why there is none
  bool timedOut = false;  // the child did not answer within the deadline and was killed
};

// The probe of `driver` on the GL backend `backend`, in a child process.
ProbeResult probeInChild(const std::string& backend, const std::string& driver);

// What the `probe-driver` child writes on its standard output: "ok" and the
// four strings, or "error" and the reason, one a line.
std::string probeAnswer(const std::function<DeviceInfo()>& probe);

// The probe's deadline: LIGHTCTS_PROBE_TIMEOUT_S, default 30 s.
int probeTimeoutSeconds();

// A driver whose probe timed out: listed as Timeout, and like any absent
// driver never a pass.
class ProbeTimeoutError : public NotSupportedError {
 public:
  using NotSupportedError::NotSupportedError;
};

}  // namespace backends::gl
