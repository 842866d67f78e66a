// The five backend and driver combinations the suite runs (SPEC 10 test
// names end in their suffix). `lightcts run --backend` takes a suffix, or an
// API backend name, which stands for all its combinations.
#pragma once

#include <string>
#include <vector>

namespace runner {

struct BackendCombination {
  std::string suffix;   // vulkan, gl-egl, gl-osmesa, gl-egl-softpipe, gl-osmesa-softpipe
  std::string backend;  // --backend: vulkan | gl-egl | gl-osmesa
  std::string driver;   // --driver: "" (the backend's default), llvmpipe or softpipe
};

const std::vector<BackendCombination>& backendCombinations();

// The combinations `names` asks for, in backendCombinations() order and
// without repeats; every combination when `names` is empty. Throws
// std::invalid_argument naming the first unknown name.
std::vector<BackendCombination> selectCombinations(const std::vector<std::string>& names);

}  // namespace runner
