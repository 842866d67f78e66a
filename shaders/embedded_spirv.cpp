#include "shaders/embedded_spirv.h"

#include <stdexcept>

// Written at build time (CMakeLists.txt): glslangValidator --vn, and
// SPIRV-Cross output wrapped by embed_text.cmake; each stage's model build
// and its admissible variants' build (<stage>_variants).
#include "spirv/forward_vert.h"
#include "spirv/forward_vert_variants.h"
#include "spirv/forward_frag.h"
#include "spirv/forward_frag_variants.h"
#include "spirv/gbuffer_frag.h"
#include "spirv/gbuffer_frag_variants.h"
#include "spirv/deferred_light_vert.h"
#include "spirv/deferred_light_vert_variants.h"
#include "spirv/deferred_light_frag.h"
#include "spirv/deferred_light_frag_variants.h"
#include "spirv/deferred_composite_vert.h"
#include "spirv/deferred_composite_vert_variants.h"
#include "spirv/deferred_composite_frag.h"
#include "spirv/deferred_composite_frag_variants.h"
#include "spirv/shadow_caster_vert.h"
#include "spirv/shadow_caster_vert_variants.h"
#include "spirv/shadow_caster_frag.h"
#include "spirv/shadow_caster_frag_variants.h"
#include "glsl330/forward_vert.h"
#include "glsl330/forward_vert_variants.h"
#include "glsl330/forward_frag.h"
#include "glsl330/forward_frag_variants.h"
#include "glsl330/gbuffer_frag.h"
#include "glsl330/gbuffer_frag_variants.h"
#include "glsl330/deferred_light_vert.h"
#include "glsl330/deferred_light_vert_variants.h"
#include "glsl330/deferred_light_frag.h"
#include "glsl330/deferred_light_frag_variants.h"
#include "glsl330/deferred_composite_vert.h"
#include "glsl330/deferred_composite_vert_variants.h"
#include "glsl330/deferred_composite_frag.h"
#include "glsl330/deferred_composite_frag_variants.h"
#include "glsl330/shadow_caster_vert.h"
#include "glsl330/shadow_caster_vert_variants.h"
#include "glsl330/shadow_caster_frag.h"
#include "glsl330/shadow_caster_frag_variants.h"

namespace shaders {

std::span<const std::uint32_t> spirv(Stage stage, ShaderBuild build) {
  const bool variants = build == ShaderBuild::AdmissibleVariants;
  switch (stage) {
    case Stage::ForwardVertex: return variants ? std::span<const std::uint32_t>(forward_vert_variants_spirv) : std::span<const std::uint32_t>(forward_vert_spirv);
    case Stage::ForwardFragment: return variants ? std::span<const std::uint32_t>(forward_frag_variants_spirv) : std::span<const std::uint32_t>(forward_frag_spirv);
    case Stage::GbufferFragment: return variants ? std::span<const std::uint32_t>(gbuffer_frag_variants_spirv) : std::span<const std::uint32_t>(gbuffer_frag_spirv);
    case Stage::DeferredLightVertex: return variants ? std::span<const std::uint32_t>(deferred_light_vert_variants_spirv) : std::span<const std::uint32_t>(deferred_light_vert_spirv);
    case Stage::DeferredLightFragment: return variants ? std::span<const std::uint32_t>(deferred_light_frag_variants_spirv) : std::span<const std::uint32_t>(deferred_light_frag_spirv);
    case Stage::DeferredCompositeVertex: return variants ? std::span<const std::uint32_t>(deferred_composite_vert_variants_spirv) : std::span<const std::uint32_t>(deferred_composite_vert_spirv);
    case Stage::DeferredCompositeFragment: return variants ? std::span<const std::uint32_t>(deferred_composite_frag_variants_spirv) : std::span<const std::uint32_t>(deferred_composite_frag_spirv);
    case Stage::ShadowCasterVertex: return variants ? std::span<const std::uint32_t>(shadow_caster_vert_variants_spirv) : std::span<const std::uint32_t>(shadow_caster_vert_spirv);
    case Stage::ShadowCasterFragment: return variants ? std::span<const std::uint32_t>(shadow_caster_frag_variants_spirv) : std::span<const std::uint32_t>(shadow_caster_frag_spirv);
  }
  throw std::invalid_argument("shaders::spirv: not a Stage");
}

std::string_view glsl330(Stage stage, ShaderBuild build) {
  const bool variants = build == ShaderBuild::AdmissibleVariants;
  switch (stage) {
    case Stage::ForwardVertex: return variants ? forward_vert_variants_glsl330 : forward_vert_glsl330;
    case Stage::ForwardFragment: return variants ? forward_frag_variants_glsl330 : forward_frag_glsl330;
    case Stage::GbufferFragment: return variants ? gbuffer_frag_variants_glsl330 : gbuffer_frag_glsl330;
    case Stage::DeferredLightVertex: return variants ? deferred_light_vert_variants_glsl330 : deferred_light_vert_glsl330;
    case Stage::DeferredLightFragment: return variants ? deferred_light_frag_variants_glsl330 : deferred_light_frag_glsl330;
    case Stage::DeferredCompositeVertex: return variants ? deferred_composite_vert_variants_glsl330 : deferred_composite_vert_glsl330;
    case Stage::DeferredCompositeFragment: return variants ? deferred_composite_frag_variants_glsl330 : deferred_composite_frag_glsl330;
    case Stage::ShadowCasterVertex: return variants ? shadow_caster_vert_variants_glsl330 : shadow_caster_vert_glsl330;
    case Stage::ShadowCasterFragment: return variants ? shadow_caster_frag_variants_glsl330 : shadow_caster_frag_glsl330;
  }
  throw std::invalid_argument("shaders::glsl330: not a Stage");
}

}  // namespace shaders
