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

const NamedVulkanDriver& lavapipeDriver() {
  // Mesa names the manifest after the CPU it was built for (meson's
  // host_machine.cpu()); Debian installs it in the loader's search path.
#if defined(__x86_64__)
  constexpr const char* kCpu = "x86_64";
#elif defined(__aarch64__)
  constexpr const char* kCpu = "aarch64";
#elif defined(__i386__)
  constexpr const char* kCpu = "i686";
#else
  constexpr const char* kCpu = "unknown-cpu";  // no such manifest: lavapipe is NotSupported
#endif
  static const NamedVulkanDriver lavapipe = {"lavapipe", "lavapipe",
                                             std::string("/usr/share/vulkan/icd.d/lvp_icd.") + kCpu + ".json",
                                             "mesa-vulkan-drivers", vk::DriverId::eMesaLlvmpipe};
  return lavapipe;
}

std::vector<std::pair<std::string, std::string>> onlyDriverVariables(const std::string& manifest) {
  return {{"VK_DRIVER_FILES", manifest}, {"VK_ICD_FILENAMES", manifest}};
}

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
