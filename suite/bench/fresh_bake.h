// The bake both benchmark programs time: one that neither reads nor writes
// the bake cache, so every bake is a fresh one, timed whole.
#pragma once

#include "baking/bake.h"

namespace bench {

inline baking::BakeOptions freshBake() {
  baking::BakeOptions options;
  options.useCache = false;
  return options;
}

}  // namespace bench
