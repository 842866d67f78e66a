// What results.json says about where and when a run happened, so a report
// from a vendor can be read without asking.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

namespace runner {

std::string revision();      // `git describe --always --dirty` of the source at build time, or "unknown"
std::string utcTimestamp();  // now, ISO 8601 UTC: 2026-12-01T15:04:05Z
nlohmann::ordered_json machineJson();  // hostname, cpu, cores, os
// {"kind": kind, "path": path, "sha256": hex digest of its bytes}: a file
// that decided how a run was chosen or judged (a caselist, an
// expected-failures file), so a result says exactly how it was made. Throws
// std::invalid_argument when the file cannot be read.
nlohmann::ordered_json baselineFileJson(const std::string& kind, const std::string& path);

}  // namespace runner
