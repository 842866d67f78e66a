// What results.json says about where and when a run happened, so a report
// from a vendor can be read without asking.
#pragma once

#include "results/run_records.h"

#include <string>

namespace runner {

std::string revision();      // `git describe --always --dirty` of the source at build time, or "unknown"
std::string utcTimestamp();  // now, ISO 8601 UTC: 2026-12-01T15:04:05Z
results::MachineRecord thisMachine();  // hostname, cpu, cores, os
// A file that decided how a run was chosen or judged (a caselist, an
// expected-failures file) with the digest of its bytes, so a result says
// exactly how it was made. Throws std::invalid_argument when the file cannot
// be read.
results::BaselineFile baselineFile(const std::string& kind, const std::string& path);

}  // namespace runner
