// The check that the driver a run loaded is the one the vendor asked for
// (`--expect-driver`, docs/vendors.md): a silent fallback to another driver
// (a Vulkan ICD that failed to load, a GL context on the wrong Mesa driver)
// must never produce a pass.
#pragma once

#include "backends/backend.h"

#include <string>

namespace backends {

// True when `expected` is empty or, ignoring case, part of the device's name,
// driver or driver version.
bool deviceMatches(const DeviceInfo& device, const std::string& expected);

// Throws DriverError naming what was asked for and what was loaded.
void requireExpectedDriver(const DeviceInfo& device, const std::string& expected);

}  // namespace backends
