// The lines a worker (`lightcts worker`, runner/suite_worker.cpp) writes on
// its standard output and `lightcts run` reads (runner/part_run.cpp): one
// JSON object a line, its "kind" one of the words below. Both sides spell
// the words from here. A line that is no JSON object is a driver's own
// output and is skipped.
//   {"kind": "device", "device": {...}}               the backend is up (once)
//   {"kind": "result", "index": i, ...}               task i's result (results::TaskResult)
//   {"kind": "backend_unavailable", "message": "..."} the backend is not here: NotSupported, the run skips the rest
//   {"kind": "backend_error", "message": "..."}       the backend could not be built (driver error,
//                                                     --expect-driver mismatch)
#pragma once

#include "results/run_records.h"

#include <cstddef>
#include <string_view>

namespace runner::protocol {

inline constexpr std::string_view kKind = "kind";
inline constexpr std::string_view kDevice = "device";
inline constexpr std::string_view kResult = "result";
inline constexpr std::string_view kBackendUnavailable = "backend_unavailable";
inline constexpr std::string_view kBackendError = "backend_error";
// The fields beside "kind": the device's description, the task's index in
// the worker's plan, and a backend line's reason.
inline constexpr std::string_view kDeviceField = "device";
inline constexpr std::string_view kIndex = "index";
inline constexpr std::string_view kMessage = "message";

// Task `index`'s "result" line, as both a worker and a stand-in write it.
inline nlohmann::ordered_json resultLine(std::size_t index, const results::TaskResult& result) {
  nlohmann::ordered_json line = {{kKind, kResult}, {kIndex, index}};
  line.update(result.toJson());
  return line;
}

}  // namespace runner::protocol
