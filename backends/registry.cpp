#include "backends/backend.h"

namespace backends {

const std::vector<std::string>& specBackendNames() {
  static const std::vector<std::string> names = {"vulkan", "gl-egl", "gl-osmesa"};
  return names;
}

const std::vector<BackendEntry>& compiledBackends() {
  static const std::vector<BackendEntry> entries;
  return entries;
}

const BackendEntry* findCompiledBackend(const std::string& name) {
  for (const BackendEntry& entry : compiledBackends())
    if (entry.name == name) return &entry;
  return nullptr;
}

}  // namespace backends
