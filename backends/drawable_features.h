// What a frame asks for that neither backend draws yet: SPEC 3.10's light
// cookies (issue 18), which the loader, the reference and the packing
// already handle. Both backends call this first in preparePipeline and
// draw, so such a frame is NotSupported (exit 3), never a pass, and the
// reference still renders it.
#pragma once

#include "lighting/frame.h"

namespace backends {

// Throws NotSupportedError naming what the frame needs.
void requireDrawableFeatures(const lighting::Frame& frame);

}  // namespace backends
