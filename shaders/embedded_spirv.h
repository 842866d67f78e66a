// The shader stages, compiled from this folder's GLSL at build time and
// linked into the binary: SPIR-V for Vulkan, and the GLSL 330 that
// SPIRV-Cross makes of the same SPIR-V for OpenGL (CMakeLists.txt).
#pragma once

#include <cstdint>
#include <span>
#include <string_view>

namespace shaders {

// Forward path; forward.vert is also the deferred G-buffer pass's vertex stage.
std::span<const std::uint32_t> forwardVertexSpirv();
std::span<const std::uint32_t> forwardFragmentSpirv();
// Deferred path (SPEC 3.7): G-buffer fragment stage, light pass (one draw per
// light volume), composite (full-screen triangle from gl_VertexIndex, 3
// vertices, no vertex input).
std::span<const std::uint32_t> gbufferFragmentSpirv();
std::span<const std::uint32_t> deferredLightVertexSpirv();
std::span<const std::uint32_t> deferredLightFragmentSpirv();
std::span<const std::uint32_t> deferredCompositeVertexSpirv();
std::span<const std::uint32_t> deferredCompositeFragmentSpirv();
// The depth-only shadow-map pass (SPEC 3.9): one draw per object per view.
std::span<const std::uint32_t> shadowCasterVertexSpirv();
std::span<const std::uint32_t> shadowCasterFragmentSpirv();

// GLSL 330 core; each specialization constant n is a macro
// SPIRV_CROSS_CONSTANT_ID_n with the shader's default unless defined first.
std::string_view forwardVertexGlsl330();
std::string_view forwardFragmentGlsl330();
std::string_view gbufferFragmentGlsl330();
std::string_view deferredLightVertexGlsl330();
std::string_view deferredLightFragmentGlsl330();
std::string_view deferredCompositeVertexGlsl330();
std::string_view deferredCompositeFragmentGlsl330();
std::string_view shadowCasterVertexGlsl330();
std::string_view shadowCasterFragmentGlsl330();

}  // namespace shaders
