// The JSON of `lightcts lights` (SPEC 5.4).
#pragma once

#include "lighting/frame.h"

#include <nlohmann/json.hpp>

namespace lighting {

// {"visible": [...], "objects": [...], "shadow_mask": [...]}, keys in SPEC order.
// `shadow_mask` lists the candidates of SPEC 5.3 in assignment order.
nlohmann::ordered_json selectionToJson(const Frame& frame);

}  // namespace lighting
