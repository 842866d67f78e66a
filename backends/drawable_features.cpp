#include "backends/drawable_features.h"

#include "backends/backend.h"

namespace backends {

void requireDrawableFeatures(const lighting::Frame& frame) {
  if (!frame.cookies.overflow.empty()) throw NotSupportedError(frame.cookies.overflow);
  if (!frame.shadows.overflow.empty()) throw NotSupportedError(frame.shadows.overflow);
}

}  // namespace backends
