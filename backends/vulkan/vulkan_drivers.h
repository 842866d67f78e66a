// The Vulkan drivers a run can name with --driver, beside the loader's own
// choice (no --driver: every driver the loader finds, lavapipe on Debian).
// A named driver is loaded from its own ICD manifest and nothing else, and a
// device counts only when it reports that driver's VkDriverId, so a run that
// asks for SwiftShader can never silently run on lavapipe instead.
#pragma once

#include "backends/vulkan/vulkan_api.h"

#include <string>
#include <string_view>
#include <utility>
#include <vector>

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

// lavapipe, Mesa's Vulkan driver on llvmpipe: the one Vulkan driver that
// zink (Mesa's OpenGL on Vulkan, the combination gl-egl-zink) draws through
// (backends/gl/mesa_driver.cpp). Not a --driver of the Vulkan backend, whose
// own choice is lavapipe on Debian already.
const NamedVulkanDriver& lavapipeDriver();

// The loader's variables that make `manifest` its only driver, for a
// ScopedEnvironment (backends/scoped_environment.h) held while an instance
// is created: VK_DRIVER_FILES, the loader's current name, and
// VK_ICD_FILENAMES, the one older loaders read (Debian 12's reads both).
std::vector<std::pair<std::string, std::string>> onlyDriverVariables(const std::string& manifest);

}  // namespace backends::vulkan
