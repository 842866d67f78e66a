// The G-buffer's samplers (shaders/deferred_data.glsl) in
// lighting::GbufferTarget order, the order both backends make and bind the
// targets in; their bindings are in shaders/shader_interface.def.
#pragma once

#include "lighting/deferred_lights.h"
#include "shaders/shader_interface.h"  // generated from shaders/shader_interface.def

#include <array>

namespace shaders {

inline constexpr std::array<binding::Texture, lighting::kGbufferTargetCount> kGbufferTextures = {
    binding::kGbufferAlbedo, binding::kGbufferNormal, binding::kGbufferBase, binding::kGbufferMask,
    binding::kGbufferMaterial};
static_assert(int(lighting::GbufferTarget::Albedo) == 0 && int(lighting::GbufferTarget::Normal) == 1 &&
              int(lighting::GbufferTarget::Base) == 2 && int(lighting::GbufferTarget::Mask) == 3 &&
              int(lighting::GbufferTarget::Material) == 4);

}  // namespace shaders
