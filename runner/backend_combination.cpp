#include "runner/backend_combination.h"

#include <algorithm>
#include <stdexcept>

namespace runner {

const std::vector<BackendCombination>& backendCombinations() {
  static const std::vector<BackendCombination> all = {
      {"vulkan", "vulkan", ""},
      {"gl-egl", "gl-egl", "llvmpipe"},
      {"gl-osmesa", "gl-osmesa", "llvmpipe"},
      {"gl-egl-softpipe", "gl-egl", "softpipe"},
      {"gl-osmesa-softpipe", "gl-osmesa", "softpipe"},
  };
  return all;
}

std::vector<BackendCombination> selectCombinations(const std::vector<std::string>& names) {
  if (names.empty()) return backendCombinations();
  std::vector<bool> chosen(backendCombinations().size(), false);
  for (const std::string& name : names) {
    bool known = false;
    for (std::size_t i = 0; i < backendCombinations().size(); ++i) {
      const BackendCombination& c = backendCombinations()[i];
      // "gl-egl" names the API backend: llvmpipe and softpipe both.
      if (c.suffix == name || c.backend == name) chosen[i] = known = true;
    }
    if (!known)
      throw std::invalid_argument("unknown backend '" + name +
                                  "'; expected one of: vulkan, gl-egl, gl-osmesa, gl-egl-softpipe, gl-osmesa-softpipe");
  }
  std::vector<BackendCombination> selected;
  for (std::size_t i = 0; i < chosen.size(); ++i)
    if (chosen[i]) selected.push_back(backendCombinations()[i]);
  return selected;
}

}  // namespace runner
