#include "backends/drawable_features.h"

#include "backends/backend.h"

namespace backends {

void requireDrawableFeatures(const lighting::Frame& frame) {
  if (!frame.cookies.overflow.empty()) throw NotSupportedError(frame.cookies.overflow);
  if (!frame.features.cookies) return;
  const lighting::CookieSlots& slots = frame.cookies;
  const int light = slots.textureLights.empty() ? slots.cubeLights.front() : slots.textureLights.front();
  throw NotSupportedError("light '" + frame.scene().lights[light].name +
                          "' has a cookie (SPEC 3.10), which the backends do not draw yet");
}

}  // namespace backends
