// Every backend and Mesa driver pair of SPEC 10's test names, for tests that
// run on each. gtest_discover_tests runs every test in its own process, so a
// test parameterised by combination gets the driver it asks for (Mesa loads
// one driver per process).
#pragma once

#include "backends/backend.h"

#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace backends::testing {

struct Combination {
  std::string suffix;   // the test-name suffix: vulkan, gl-egl-softpipe, ...
  std::string backend;  // SPEC 8 name
  std::string driver;   // --driver, empty for the backend's default
};

// How gtest names a combination (test names stay readable).
inline void PrintTo(const Combination& c, std::ostream* out) { *out << c.suffix; }

inline std::vector<Combination> allCombinations() {
  return {{"vulkan", "vulkan", ""},
          {"gl_egl", "gl-egl", "llvmpipe"},
          {"gl_osmesa", "gl-osmesa", "llvmpipe"},
          {"gl_egl_softpipe", "gl-egl", "softpipe"},
          {"gl_osmesa_softpipe", "gl-osmesa", "softpipe"}};
}

// The backend with validation on, or null with `whyNot` set when it is not
// supported here (a skip). Other failures throw.
inline std::unique_ptr<Backend> createOrNull(const Combination& c, std::string& whyNot) {
  const BackendEntry* entry = findCompiledBackend(c.backend);
  if (!entry) {
    whyNot = c.backend + " is not built";
    return nullptr;
  }
  BackendOptions options;
  options.driver = c.driver;
  options.validation = true;
  try {
    return entry->create(options);
  } catch (const NotSupportedError& e) {
    whyNot = c.suffix + ": " + e.what();
    return nullptr;
  }
}

}  // namespace backends::testing
