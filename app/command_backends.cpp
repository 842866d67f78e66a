#include "app/commands.h"
#include "app/exit_status.h"
#include "app/scene_input.h"
#include "backends/backend.h"

#include <algorithm>
#include <ostream>

namespace app {
namespace {

// The backend a render or compare asks for: unknown names are usage errors
// (exit 2); a SPEC backend this build lacks is a skip (exit 3), never a pass.
const backends::BackendEntry* resolveBackend(const std::string& name, std::ostream& err, int& status) {
  const auto& known = backends::specBackendNames();
  if (std::find(known.begin(), known.end(), name) == known.end()) {
    err << "lightcts: unknown backend '" << name << "'; expected one of: vulkan, gl-egl, gl-osmesa\n";
    status = kExitBadInput;
    return nullptr;
  }
  const backends::BackendEntry* entry = backends::findCompiledBackend(name);
  if (!entry) {
    err << "lightcts: backend '" << name << "' is not supported by this build (NotSupported)\n";
    status = kExitNotSupported;
  }
  return entry;
}

}  // namespace

int runBackendsCommand(std::ostream& out, std::ostream& err) {
  return guardCommand(err, [&] {
    for (const std::string& name : backends::specBackendNames()) {
      const backends::BackendEntry* entry = backends::findCompiledBackend(name);
      if (!entry) {
        out << name << ": not built (NotSupported)\n";
        continue;
      }
      const auto devices = entry->listDevices({});
      if (devices.empty()) out << name << ": no device (NotSupported)\n";
      for (std::size_t i = 0; i < devices.size(); ++i)
        out << name << " [" << i << "] " << devices[i].name << ", driver " << devices[i].driver << " "
            << devices[i].driverVersion << ", API " << devices[i].apiVersion << "\n";
    }
    return kExitSuccess;
  });
}

int runRenderCommand(const SceneArguments& args, const BackendArguments& backend, const std::string& outFile,
                     std::ostream&, std::ostream& err) {
  return guardCommand(err, [&] {
    const SceneInput input = loadSceneInput(args);  // a bad scene is exit 2 before anything else
    (void)input;
    (void)outFile;
    int status = kExitSuccess;
    if (!resolveBackend(backend.backend, err, status)) return status;
    return kExitNotSupported;
  });
}

int runCompareCommand(const SceneArguments& args, const BackendArguments& backend, std::ostream&,
                      std::ostream& err) {
  return guardCommand(err, [&] {
    const SceneInput input = loadSceneInput(args);
    (void)input;
    int status = kExitSuccess;
    if (!resolveBackend(backend.backend, err, status)) return status;
    return kExitNotSupported;
  });
}

int runSuiteCommand(const std::vector<std::string>& names, const std::string&, const std::string&, std::ostream&,
                    std::ostream& err) {
  return guardCommand(err, [&] {
    for (const std::string& name : names) {
      int status = kExitSuccess;
      if (!resolveBackend(name, err, status) && status == kExitBadInput) return status;
    }
    err << "lightcts: run: the whole-suite runner is not supported by this build yet (NotSupported)\n";
    return kExitNotSupported;
  });
}

}  // namespace app
