#include "app/backend_choice.h"
#include "app/commands.h"
#include "app/exit_status.h"
#include "app/scene_input.h"

#include <ostream>

namespace app {

int runBackendsCommand(std::ostream& out, std::ostream& err) {
  return guardCommand(err, [&] {
    for (const std::string& name : backends::specBackendNames()) {
      const backends::BackendEntry* entry = backends::findBuiltBackendEntry(name);
      if (!entry) {
        out << name << ": not built (NotSupported)\n";
        continue;
      }
      std::vector<backends::DeviceInfo> devices;
      try {
        devices = entry->listDevices({});
      } catch (const backends::NotSupportedError& e) {
        out << name << ": " << e.what() << " (NotSupported)\n";
        continue;
      }
      if (devices.empty()) out << name << ": no device (NotSupported)\n";
      for (std::size_t i = 0; i < devices.size(); ++i)
        out << name << " [" << devices[i].selectedBy << "] " << devices[i].name << ", driver " << devices[i].driver << ", driver version "
            << devices[i].driverVersion << ", API " << devices[i].apiVersion << "\n";
    }
    return kExitSuccess;
  });
}

}  // namespace app
