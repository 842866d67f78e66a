#include "backends/gl/shared_library.h"

#include "backends/backend.h"

#include <dlfcn.h>

namespace backends::gl {

SharedLibrary::SharedLibrary(const std::vector<std::string>& names) {
  for (const std::string& name : names) {
    handle_ = ::dlopen(name.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle_) {
      name_ = name;
      return;
    }
  }
  std::string tried;
  for (const std::string& name : names) tried += (tried.empty() ? "" : ", ") + name;
  throw NotSupportedError("cannot open " + tried + " (is the package installed?)");
}

SharedLibrary::~SharedLibrary() {
  if (handle_) ::dlclose(handle_);
}

void* SharedLibrary::find(const char* symbol) const { return ::dlsym(handle_, symbol); }

void* SharedLibrary::requireSymbol(const char* symbol) const {
  void* address = find(symbol);
  if (!address) throw NotSupportedError(name_ + " has no " + symbol);
  return address;
}

}  // namespace backends::gl
