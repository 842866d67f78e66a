// The shader stages, compiled from this folder's GLSL at build time and
// linked into the binary: SPIR-V for Vulkan, and the GLSL 330 that
// SPIRV-Cross makes of the same SPIR-V for OpenGL (CMakeLists.txt).
#pragma once

#include <cstdint>
#include <span>
#include <string_view>

namespace shaders {

std::span<const std::uint32_t> forwardVertexSpirv();
std::span<const std::uint32_t> forwardFragmentSpirv();

// GLSL 330 core; each specialization constant n is a macro
// SPIRV_CROSS_CONSTANT_ID_n with the shader's default unless defined first.
std::string_view forwardVertexGlsl330();
std::string_view forwardFragmentGlsl330();

}  // namespace shaders
