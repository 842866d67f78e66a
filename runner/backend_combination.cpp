#include "runner/backend_combination.h"

#include <stdexcept>

namespace runner {

std::vector<BackendCombination> selectCombinations(const std::vector<std::string>& names) {
  const std::vector<BackendCombination>& all = backendCombinations();
  if (names.empty()) return all;
  std::vector<bool> chosen(all.size(), false);
  for (const std::string& name : names) {
    bool known = false;
    for (std::size_t i = 0; i < all.size(); ++i) {
      // "gl-egl" names the API backend: llvmpipe and softpipe both.
      if (all[i].suffix == name || all[i].backend == name) chosen[i] = known = true;
    }
    if (!known)
      throw std::invalid_argument("unknown backend '" + name + "'; expected one of: " +
                                  backends::combinationSuffixList());
  }
  std::vector<BackendCombination> selected;
  for (std::size_t i = 0; i < chosen.size(); ++i)
    if (chosen[i]) selected.push_back(all[i]);
  return selected;
}

}  // namespace runner
