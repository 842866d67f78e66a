#include "backends/expected_driver.h"

#include <algorithm>
#include <cctype>

namespace backends {
namespace {

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return text;
}

}  // namespace

bool deviceMatches(const DeviceInfo& device, const std::string& expected) {
  if (expected.empty()) return true;
  const std::string wanted = lower(expected);
  for (const std::string* field : {&device.name, &device.driver, &device.driverVersion})
    if (lower(*field).find(wanted) != std::string::npos) return true;
  return false;
}

void requireExpectedDriver(const DeviceInfo& device, const std::string& expected) {
  if (!deviceMatches(device, expected))
    throw DriverError("--expect-driver '" + expected + "' does not match the loaded device: '" + device.name +
                      "', driver '" + device.driver + "' " + device.driverVersion +
                      " (a fallback to another driver never passes)");
}

}  // namespace backends
