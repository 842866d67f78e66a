// Which of the combinations of the one table (backends/backend_combinations.h)
// a run asks for. `lightcts run --backend` takes a suffix, or an API backend
// name, which stands for all its combinations.
#pragma once

#include "backends/backend_combinations.h"

#include <string>
#include <vector>

namespace runner {

using backends::BackendCombination;
using backends::backendCombinations;

// The combinations `names` asks for, in backendCombinations() order and
// without repeats; every combination when `names` is empty. Throws
// std::invalid_argument naming the first unknown name.
std::vector<BackendCombination> selectCombinations(const std::vector<std::string>& names);

// The same, with `run --driver NAME` (any Mesa Gallium driver, as `compare`
// takes it): the GL combinations chosen become one per GL API backend with
// that driver (combinationWithDriver); Vulkan's are as chosen. Throws
// std::invalid_argument when no GL backend is chosen, or when a combination
// named with its own driver (gl-egl-softpipe) is given another.
std::vector<BackendCombination> selectCombinations(const std::vector<std::string>& names, const std::string& driver);

}  // namespace runner
