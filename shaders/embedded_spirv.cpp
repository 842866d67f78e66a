#include "shaders/embedded_spirv.h"

// Written by glslangValidator --vn at build time (CMakeLists.txt).
#include "spirv/forward_vert.h"
#include "spirv/forward_frag.h"

namespace shaders {

std::span<const std::uint32_t> forwardVertexSpirv() { return forward_vert_spirv; }
std::span<const std::uint32_t> forwardFragmentSpirv() { return forward_frag_spirv; }

}  // namespace shaders
