// The SPIR-V of every shader stage, compiled from this folder's GLSL at build
// time and linked into the binary. Vulkan uses it as is; the OpenGL backend
// turns the same words into GLSL with SPIRV-Cross.
#pragma once

#include <cstdint>
#include <span>

namespace shaders {

std::span<const std::uint32_t> forwardVertexSpirv();
std::span<const std::uint32_t> forwardFragmentSpirv();

}  // namespace shaders
