#include "app/backend_choice.h"

#include "app/exit_status.h"
#include "app/scene_input.h"

#include <algorithm>
#include <filesystem>

namespace app {

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

backends::BackendOptions backendOptions(const BackendArguments& args) {
  backends::BackendOptions options;
  options.device = args.device;
  options.driver = args.driver;
  options.validation = backends::validationRequestedByDefault();
  options.variant.specialised = !args.fullShader;
  const auto mutant = shaders::mutantFromName(args.mutant);
  if (!mutant) {
    std::string known = "none";
    for (const auto& m : shaders::mutantNames()) known += ", " + std::string(m.name);
    throw InputError("unknown --mutant '" + args.mutant + "'; expected one of: " + known);
  }
  options.variant.mutant = *mutant;
  return options;
}

std::string caseName(const std::string& scenePath, const BackendArguments& args) {
  const std::filesystem::path path(scenePath);
  std::string backend = args.backend;
  // The GL backends' non-default driver is part of the case (SPEC 10 names
  // gl-egl-softpipe and gl-osmesa-softpipe).
  if (!args.driver.empty() && args.driver != "llvmpipe") backend += "-" + args.driver;
  return path.parent_path().filename().string() + "." + path.stem().string() + "." + backend;
}

}  // namespace app
