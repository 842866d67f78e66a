#include "backends/backend.h"

#include "backends/gl/gl_backend.h"
#include "backends/vulkan/vulkan_backend.h"

#include <cstdlib>
#include <string_view>

namespace backends {

const std::vector<std::string>& specBackendNames() {
  static const std::vector<std::string> names = {"vulkan", "gl-egl", "gl-osmesa"};
  return names;
}

bool validationRequestedByDefault() {
#ifndef NDEBUG
  return true;
#else
  const char* value = std::getenv("LIGHTCTS_VALIDATION");
  return value && std::string_view(value) == "1";
#endif
}

const std::vector<BackendEntry>& builtBackendEntries() {
  static const std::vector<BackendEntry> entries = {vulkan::vulkanBackendEntry(), gl::eglBackendEntry(),
                                                    gl::osmesaBackendEntry()};
  return entries;
}

const BackendEntry* findBuiltBackendEntry(const std::string& name) {
  for (const BackendEntry& entry : builtBackendEntries())
    if (entry.name == name) return &entry;
  return nullptr;
}

}  // namespace backends
