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
      // "gl-egl" names the API backend: llvmpipe and softpipe both. "vulkan"
      // names the loader's own driver alone (a vendor's ICD, or lavapipe): a
      // Vulkan driver the table names is chosen by its suffix
      // (vulkan-swiftshader) or by --driver.
      if (all[i].suffix == name || (all[i].backend == name && all[i].takesMesaDriver())) chosen[i] = known = true;
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
  // A Vulkan driver's name (swiftshader) moves the Vulkan combinations to
  // it; any other name is a Mesa driver and moves the GL combinations. The
  // combinations of the other API keep their own driver.
  const BackendCombination* vulkanDriver = backends::vulkanDriverCombination(driver);
  const bool namesVulkanDriver = vulkanDriver != nullptr;
  std::vector<BackendCombination> withDriver;
  bool anyMoved = false;
  for (const BackendCombination& c : chosen) {
    const bool moves = c.takesMesaDriver() != namesVulkanDriver;
    const BackendCombination one =
        !moves ? c : namesVulkanDriver ? *vulkanDriver : backends::combinationWithDriver(c.backend, driver);
    anyMoved = anyMoved || moves;
    const bool seen = std::any_of(withDriver.begin(), withDriver.end(),
                                  [&](const BackendCombination& w) { return w.suffix == one.suffix; });
    if (!seen) withDriver.push_back(one);
  }
  if (!anyMoved)
    throw std::invalid_argument("--driver '" + driver + "' chooses a " + (namesVulkanDriver ? "Vulkan" : "GL") +
                                " driver, and no " + (namesVulkanDriver ? "Vulkan" : "GL") + " backend is run");
  return withDriver;
}

}  // namespace runner
