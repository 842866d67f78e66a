// What a frame asks for that no backend can draw: more cookies among its
// kept lights than the texture slots (lighting/cookie_slots.h). Both
// backends call this first in preparePipeline and draw, so such a frame is
// NotSupported (exit 3), never a pass, and the reference still renders it.
#pragma once

#include "lighting/frame.h"

namespace backends {

// Throws NotSupportedError naming what the frame needs.
void requireDrawableFeatures(const lighting::Frame& frame);

}  // namespace backends
