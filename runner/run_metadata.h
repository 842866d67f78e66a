// What results.json says about where and when a run happened, so a report
// from a vendor can be read without asking.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

namespace runner {

std::string revision();      // `git describe --always --dirty` of the source at build time, or "unknown"
std::string utcTimestamp();  // now, ISO 8601 UTC: 2026-12-01T15:04:05Z
nlohmann::ordered_json machineJson();  // hostname, cpu, cores, os

}  // namespace runner
