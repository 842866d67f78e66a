#include "app/backend_choice.h"
#include "app/commands.h"
#include "app/exit_status.h"
#include "app/scene_input.h"
#include "backends/backend_combinations.h"
#include "backends/gl/probe_in_child.h"

#include <algorithm>
#include <ostream>

namespace app {
namespace {

// The drivers `lightcts backends` probes on `backend`: those of its
// combinations ("" for the Vulkan loader's own choice), or the one --driver
// names: a Vulkan driver of the table on Vulkan, any other name on the GL
// backends (a Mesa driver).
std::vector<std::string> driversToProbe(const std::string& backend, const std::string& driver) {
  std::vector<std::string> tableDrivers;
  bool takesMesaDriver = false;
  const bool namesVulkanDriver = backends::vulkanDriverCombination(driver) != nullptr;
  for (const backends::BackendCombination& combination : backends::backendCombinations()) {
    if (combination.backend != backend) continue;
    takesMesaDriver = combination.takesMesaDriver();
    if (std::find(tableDrivers.begin(), tableDrivers.end(), combination.driver) == tableDrivers.end())
      tableDrivers.push_back(combination.driver);
  }
  if (driver.empty()) return tableDrivers;
  if (takesMesaDriver != namesVulkanDriver) return {driver};
  return {};
}

}  // namespace

int runBackendsCommand(std::ostream& out, std::ostream& err) { return runBackendsCommand("", out, err); }

int runBackendsCommand(const std::string& driver, std::ostream& out, std::ostream& err) {
  return guardCommand(err, [&] {
    bool found = false;
    for (const std::string& name : backends::specBackendNames()) {
      const std::vector<std::string> drivers = driversToProbe(name, driver);
      if (drivers.empty()) continue;  // --driver names a driver of the other API
      const backends::BackendEntry* entry = backends::findBuiltBackendEntry(name);
      if (!entry) {
        out << name << ": not built (NotSupported)\n";
        continue;
      }
      for (const std::string& d : drivers) {
        const std::string label = d.empty() ? name : name + " [--driver " + d + "]";
        backends::BackendOptions options;
        options.driver = d;
        std::vector<backends::DeviceInfo> devices;
        try {
          devices = entry->listDevices(options);
        } catch (const backends::gl::ProbeTimeoutError& e) {
          out << label << ": " << e.what() << " (Timeout)\n";
          continue;
        } catch (const backends::NotSupportedError& e) {
          out << label << ": " << e.what() << " (NotSupported)\n";
          continue;
        }
        if (devices.empty()) out << label << ": no device (NotSupported)\n";
        found = found || !devices.empty();
        for (const backends::DeviceInfo& device : devices)
          out << name << " [" << device.selectedBy << "] " << device.name << ", driver " << device.driver
              << ", driver version " << device.driverVersion << ", API " << device.apiVersion << "\n";
      }
    }
    // Without --driver the listing is the answer; with it, whether that
    // driver came up anywhere.
    return driver.empty() || found ? kExitSuccess : kExitNotSupported;
  });
}

}  // namespace app
