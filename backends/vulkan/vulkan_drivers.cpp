#include "backends/vulkan/vulkan_drivers.h"

#include <vector>

namespace backends::vulkan {
namespace {

const std::vector<NamedVulkanDriver>& namedDrivers() {
  // SwiftShader: Google's CPU implementation of Vulkan, an implementation
  // independent of Mesa's. Debian builds it into chromium (chromium-common)
  // and installs its manifest beside the browser, outside the loader's
  // search path, so the loader never picks it by itself.
  static const std::vector<NamedVulkanDriver> drivers = {
      {"swiftshader", "SwiftShader", "/usr/lib/chromium/vk_swiftshader_icd.json", "chromium",
       vk::DriverId::eGoogleSwiftshader},
  };
  return drivers;
}

}  // namespace

const NamedVulkanDriver* findNamedVulkanDriver(std::string_view name) {
  for (const NamedVulkanDriver& d : namedDrivers())
    if (d.name == name) return &d;
  return nullptr;
}

std::string namedVulkanDriverList() {
  std::string list;
  for (const NamedVulkanDriver& d : namedDrivers()) list += (list.empty() ? "" : ", ") + d.name;
  return list;
}

}  // namespace backends::vulkan
