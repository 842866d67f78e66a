// A shared library opened at run time (dlopen), closed when the object goes.
// The GL backends open libEGL and libOSMesa this way, so a machine without
// one of them reports NotSupported for that backend instead of failing to
// start the whole program.
#pragma once

#include <string>
#include <vector>

namespace backends::gl {

class SharedLibrary {
 public:
  // Tries each name in turn; throws NotSupportedError naming them all.
  explicit SharedLibrary(const std::vector<std::string>& names);
  ~SharedLibrary();
  SharedLibrary(const SharedLibrary&) = delete;
  SharedLibrary& operator=(const SharedLibrary&) = delete;

  // The symbol, or null.
  void* find(const char* symbol) const;
  // The symbol cast to F; throws NotSupportedError when it is missing.
  template <class F>
  F require(const char* symbol) const {
    return reinterpret_cast<F>(requireSymbol(symbol));
  }

 private:
  void* requireSymbol(const char* symbol) const;
  void* handle_ = nullptr;
  std::string name_;
};

}  // namespace backends::gl
