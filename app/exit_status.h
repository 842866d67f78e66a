// Exit statuses of the `lightcts` command (SPEC 8).
#pragma once

namespace app {

constexpr int kExitSuccess = 0;             // pass or success
constexpr int kExitConformanceFailure = 1;  // a scene failed its comparison
constexpr int kExitBadInput = 2;            // bad input or usage: malformed scene, unknown backend or option
constexpr int kExitNotSupported = 3;        // backend or feature not supported here (a skip, never a pass)
constexpr int kExitInternalError = 4;       // driver or internal error
// `run` interrupted by SIGINT or SIGTERM (docs/cli.md): 128 + the signal, as
// a shell reports a process a signal ended: 130, 143.
constexpr int kExitInterruptedBase = 128;

}  // namespace app
