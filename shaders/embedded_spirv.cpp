#include "shaders/embedded_spirv.h"

// Written at build time (CMakeLists.txt): glslangValidator --vn, and
// SPIRV-Cross output wrapped by embed_text.cmake.
#include "spirv/forward_vert.h"
#include "spirv/forward_frag.h"
#include "glsl330/forward_vert.h"
#include "glsl330/forward_frag.h"

namespace shaders {

std::span<const std::uint32_t> forwardVertexSpirv() { return forward_vert_spirv; }
std::span<const std::uint32_t> forwardFragmentSpirv() { return forward_frag_spirv; }
std::string_view forwardVertexGlsl330() { return forward_vert_glsl330; }
std::string_view forwardFragmentGlsl330() { return forward_frag_glsl330; }

}  // namespace shaders
