// How a pass rasterises, as API-neutral data (the way VK-GL-CTS's reference
// renderer carries an rr::RenderState and Filament a RasterState): the model
// decides it here, once; the Vulkan and OpenGL backends only translate the
// enums (backends/vulkan/raster_translation.h, backends/gl/raster_state_gl.h).
// Front faces are counter-clockwise in the image (SPEC 1) for every pass.
#pragma once

#include <array>
#include <compare>

namespace lighting {

enum class CullMode { None, Front, Back };
enum class DepthCompare { Always, Less, LessOrEqual, GreaterOrEqual };

struct RasterState {
  CullMode cull = CullMode::Back;
  DepthCompare depthTest = DepthCompare::Less;
  bool depthWrite = true;
  // Fragments beyond the far plane are clamped to it instead of clipped.
  bool depthClamp = false;

  auto operator<=>(const RasterState&) const = default;  // pipeline caches key on it
};

// SPEC 1: opaque surfaces, depth LESS with writes, back faces culled. The
// forward pass and the deferred G-buffer pass draw the scene's objects with it.
inline constexpr RasterState kOpaqueSurfaceState{CullMode::Back, DepthCompare::Less, true, false};

// SPEC 3.9: the shadow-map pass draws every triangle (both faces cast, no
// culling), nearest depth wins (LESS with writes, cleared to 1), depth
// clipped to [0, 1] (a caster beyond the map's far plane is not in it) and no
// rasteriser depth bias (its slope term is implementation-defined), which
// RasterState never enables.
inline constexpr RasterState kShadowCasterState{CullMode::None, DepthCompare::Less, true, false};

// What the passes clear to, decided once for both backends: depth to the far
// plane (1: with LESS the nearest surface wins; SPEC 3.9, 1 where no
// triangle covers a shadow-map texel); the image to the background, value 0
// (SPEC 6) with alpha 1 (SPEC 8: `render` writes A = 1); the G-buffer to 0
// (albedo.a = 0 marks the background for the light pass).
// The deferred light buffer clears to its blend's identity
// (lighting::lightBufferState, deferred_lights.h).
inline constexpr float kClearDepth = 1.0f;
inline constexpr std::array<float, 4> kBackgroundClear{0.0f, 0.0f, 0.0f, 1.0f};
inline constexpr std::array<float, 4> kGbufferClear{0.0f, 0.0f, 0.0f, 0.0f};

// SPEC 3.9: a lookup into a shadow map is lit when the point's depth is at
// most the texel's, so the shadow samplers compare LESS_OR_EQUAL (the
// shadow-compare-less mutant, shaders::shadowLookupCompare, makes it LESS).
inline constexpr DepthCompare kShadowLookupCompare = DepthCompare::LessOrEqual;

}  // namespace lighting
