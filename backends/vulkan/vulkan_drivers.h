// The Vulkan drivers a run can name with --driver, beside the loader's own
// choice (no --driver: every driver the loader finds, lavapipe on Debian).
// A named driver is loaded from its own ICD manifest and nothing else, and a
// device counts only when it reports that driver's VkDriverId, so a run that
// asks for SwiftShader can never silently run on lavapipe instead.
#pragma once

#include "backends/vulkan/vulkan_api.h"

#include <string>
#include <string_view>

namespace backends::vulkan {

struct NamedVulkanDriver {
  std::string name;        // --driver
  std::string title;       // how messages name it
  std::string manifest;    // its ICD manifest (the loader's VK_DRIVER_FILES)
  std::string package;     // the Debian package that installs the manifest
  vk::DriverId driverId;   // what its devices report
};

// The driver --driver `name` selects, or null.
const NamedVulkanDriver* findNamedVulkanDriver(std::string_view name);

// "swiftshader", for messages that list what --driver accepts on Vulkan.
std::string namedVulkanDriverList();

}  // namespace backends::vulkan
