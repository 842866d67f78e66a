#include "backends/backend_combinations.h"

namespace backends {

std::string BackendCombination::identifier() const {
  std::string name = suffix;
  for (char& c : name)
    if (c == '-') c = '_';
  return name;
}

const std::vector<BackendCombination>& backendCombinations() {
  static const std::vector<BackendCombination> all = {
#define LIGHTCTS_COMBINATION(suffix, backend, driver) {suffix, backend, driver},
#include "backends/backend_combinations.def"
#undef LIGHTCTS_COMBINATION
  };
  return all;
}

const BackendCombination* findCombination(std::string_view suffix) {
  for (const BackendCombination& c : backendCombinations())
    if (c.suffix == suffix) return &c;
  return nullptr;
}

const BackendCombination* findCombination(std::string_view backend, std::string_view driver) {
  for (const BackendCombination& c : backendCombinations()) {
    if (c.backend != backend) continue;
    // The default driver of a GL backend is llvmpipe: its combination is the
    // first of that backend in the table.
    if (c.driver == driver || driver.empty()) return &c;
  }
  return nullptr;
}

BackendCombination combinationWithDriver(std::string_view backend, std::string_view driver) {
  if (const BackendCombination* known = findCombination(backend, driver)) return *known;
  return {std::string(backend) + "-" + std::string(driver), std::string(backend), std::string(driver)};
}

const BackendCombination* vulkanDriverCombination(std::string_view driver) {
  if (driver.empty()) return nullptr;
  for (const BackendCombination& c : backendCombinations())
    if (!c.takesMesaDriver() && c.driver == driver) return &c;
  return nullptr;
}

std::string combinationSuffixList() {
  std::string list;
  for (const BackendCombination& c : backendCombinations()) list += (list.empty() ? "" : ", ") + c.suffix;
  return list;
}

}  // namespace backends
