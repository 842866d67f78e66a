// The backend and driver combinations the suite runs, from the one table
// in backend_combinations.def (which CMake reads too, for the ctest labels).
// `suffix` ends SPEC 10's test names and is each combination's ctest label.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace backends {

struct BackendCombination {
  std::string suffix;   // vulkan, gl-egl, gl-osmesa, gl-egl-softpipe, gl-osmesa-softpipe, vulkan-swiftshader,
                        // gl-egl-zink
  std::string backend;  // SPEC 8 --backend: vulkan | gl-egl | gl-osmesa
  std::string driver;   // --driver: "" (the backend's default), llvmpipe, softpipe, swiftshader or zink

  // A GL backend, whose --driver is any Mesa Gallium driver; Vulkan's names
  // one of the drivers the Vulkan backend knows (vulkan/vulkan_drivers.h).
  bool takesMesaDriver() const { return backend != "vulkan"; }

  // OSMesa reaches the same Mesa driver as EGL through another context
  // (client memory instead of a pbuffer), and zink draws OpenGL through
  // lavapipe: each a second path to a driver that another combination
  // already times (gl-egl, gl-egl-softpipe, vulkan), so the bench times its
  // profile modes only (docs/bench-format.md).
  bool isSecondContextPath() const { return backend == "gl-osmesa" || driver == "zink"; }
  // The suffix as a C++ identifier (gtest parameter names): '-' becomes '_'.
  std::string identifier() const;
};

// In table order.
const std::vector<BackendCombination>& backendCombinations();

// The combination with this suffix, or null.
const BackendCombination* findCombination(std::string_view suffix);
// The combination that `backend` with `driver` ("" for the default) selects,
// or null when the backend has no such driver.
const BackendCombination* findCombination(std::string_view backend, std::string_view driver);

// `backend` with `driver`: the table's combination where it has one, else
// one named "<backend>-<driver>" (a pair the table does not list, such as
// gl-osmesa with zink), so two runs on different drivers never share test
// names.
BackendCombination combinationWithDriver(std::string_view backend, std::string_view driver);

// The Vulkan combination whose driver `driver` names (swiftshader), or null
// for any other name: a --driver that is not a Vulkan driver's is a Mesa one.
const BackendCombination* vulkanDriverCombination(std::string_view driver);

// "vulkan, gl-egl, ..." for messages that list what is accepted.
std::string combinationSuffixList();

}  // namespace backends
