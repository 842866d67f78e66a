// The model's API-neutral pass state (lighting/raster_state.h, and the light
// buffer's blend of lighting/deferred_lights.h) applied to OpenGL's state
// machine. Nothing is decided here: the enums are translated to GLenums and
// every piece of the state is set, so a pass never inherits another's.
#pragma once

#include "backends/gl/gl_functions.h"
#include "lighting/deferred_lights.h"
#include "lighting/raster_state.h"

namespace backends::gl {

GLenum toGl(lighting::DepthCompare compare);

// Depth test, depth writes, culling, depth clamp, front faces CCW. OpenGL's
// window y points up like lighting::CameraView's NDC, so the meshes'
// counter-clockwise front faces stay counter-clockwise.
void applyRasterState(const GlFunctions& gl, const lighting::RasterState& raster);

// SPEC 1 for the scene's objects (forward and G-buffer passes):
// lighting::kOpaqueSurfaceState, no blending.
void applyOpaqueSurfaceState(const GlFunctions& gl);

// Add: ONE, ONE; Multiply: DST_COLOR, ZERO. Blending on.
void applyLightBlend(const GlFunctions& gl, lighting::LightBlend blend);

}  // namespace backends::gl
