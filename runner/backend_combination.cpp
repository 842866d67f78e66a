#include "runner/backend_combination.h"

#include <algorithm>
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

std::vector<BackendCombination> selectCombinations(const std::vector<std::string>& names, const std::string& driver) {
  std::vector<BackendCombination> chosen = selectCombinations(names);
  if (driver.empty()) return chosen;
  // A combination named with its driver (gl-egl-softpipe) and another --driver
  // would each say which driver runs: the run refuses rather than pick one.
  for (const std::string& name : names)
    if (const BackendCombination* named = backends::findCombination(name);
        named && named->backend != name && named->driver != driver)
      throw std::invalid_argument("--backend " + name + " runs " + named->driver + ", and --driver asks for " + driver +
                                  ": name the API backend (" + named->backend + ") with --driver");
  std::vector<BackendCombination> withDriver;
  bool anyGl = false;
  for (const BackendCombination& c : chosen) {
    // Vulkan has no --driver: its ICD is chosen by the loader (--device).
    const BackendCombination one = c.driver.empty() ? c : backends::combinationWithDriver(c.backend, driver);
    anyGl = anyGl || !c.driver.empty();
    const bool seen = std::any_of(withDriver.begin(), withDriver.end(),
                                  [&](const BackendCombination& w) { return w.suffix == one.suffix; });
    if (!seen) withDriver.push_back(one);
  }
  if (!anyGl) throw std::invalid_argument("--driver '" + driver + "' chooses a GL driver, and no GL backend is run");
  return withDriver;
}

}  // namespace runner
