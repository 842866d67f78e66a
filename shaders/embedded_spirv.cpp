#include "shaders/embedded_spirv.h"

// Written at build time (CMakeLists.txt): glslangValidator --vn, and
// SPIRV-Cross output wrapped by embed_text.cmake.
#include "spirv/forward_vert.h"
#include "spirv/forward_frag.h"
#include "spirv/gbuffer_frag.h"
#include "spirv/deferred_light_vert.h"
#include "spirv/deferred_light_frag.h"
#include "spirv/deferred_composite_vert.h"
#include "spirv/deferred_composite_frag.h"
#include "spirv/shadow_caster_vert.h"
#include "spirv/shadow_caster_frag.h"
#include "glsl330/forward_vert.h"
#include "glsl330/forward_frag.h"
#include "glsl330/gbuffer_frag.h"
#include "glsl330/deferred_light_vert.h"
#include "glsl330/deferred_light_frag.h"
#include "glsl330/deferred_composite_vert.h"
#include "glsl330/deferred_composite_frag.h"
#include "glsl330/shadow_caster_vert.h"
#include "glsl330/shadow_caster_frag.h"

namespace shaders {

std::span<const std::uint32_t> forwardVertexSpirv() { return forward_vert_spirv; }
std::span<const std::uint32_t> forwardFragmentSpirv() { return forward_frag_spirv; }
std::span<const std::uint32_t> gbufferFragmentSpirv() { return gbuffer_frag_spirv; }
std::span<const std::uint32_t> deferredLightVertexSpirv() { return deferred_light_vert_spirv; }
std::span<const std::uint32_t> deferredLightFragmentSpirv() { return deferred_light_frag_spirv; }
std::span<const std::uint32_t> deferredCompositeVertexSpirv() { return deferred_composite_vert_spirv; }
std::span<const std::uint32_t> deferredCompositeFragmentSpirv() { return deferred_composite_frag_spirv; }
std::span<const std::uint32_t> shadowCasterVertexSpirv() { return shadow_caster_vert_spirv; }
std::span<const std::uint32_t> shadowCasterFragmentSpirv() { return shadow_caster_frag_spirv; }
std::string_view forwardVertexGlsl330() { return forward_vert_glsl330; }
std::string_view forwardFragmentGlsl330() { return forward_frag_glsl330; }
std::string_view gbufferFragmentGlsl330() { return gbuffer_frag_glsl330; }
std::string_view deferredLightVertexGlsl330() { return deferred_light_vert_glsl330; }
std::string_view deferredLightFragmentGlsl330() { return deferred_light_frag_glsl330; }
std::string_view deferredCompositeVertexGlsl330() { return deferred_composite_vert_glsl330; }
std::string_view deferredCompositeFragmentGlsl330() { return deferred_composite_frag_glsl330; }

std::string_view shadowCasterVertexGlsl330() { return shadow_caster_vert_glsl330; }
std::string_view shadowCasterFragmentGlsl330() { return shadow_caster_frag_glsl330; }

}  // namespace shaders
