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

}  // namespace runner
