// The shader stages, compiled from this folder's GLSL at build time and
// linked into the binary: SPIR-V for Vulkan, and the GLSL 330 that
// SPIRV-Cross makes of the same SPIR-V for OpenGL (CMakeLists.txt).
#pragma once

#include <cstdint>
#include <span>
#include <string_view>

namespace shaders {

enum class Stage {
  // Forward path; forward.vert is also the deferred G-buffer pass's vertex stage.
  ForwardVertex,
  ForwardFragment,
  // Deferred path (SPEC 3.7): G-buffer fragment stage, light pass (one draw
  // per light volume), composite (full-screen triangle from gl_VertexIndex,
  // 3 vertices, no vertex input).
  GbufferFragment,
  DeferredLightVertex,
  DeferredLightFragment,
  DeferredCompositeVertex,
  DeferredCompositeFragment,
  // The depth-only shadow-map pass (SPEC 3.9): one draw per object per view.
  ShadowCasterVertex,
  ShadowCasterFragment,
};

// Which of a stage's two builds: the model's, which every shipped pipeline
// runs and which holds no admissible variant's code, or the admissible
// variants' (shaders/admissible.glsl), chosen by the ADMISSIBLE constant.
enum class ShaderBuild { Model, AdmissibleVariants };

std::span<const std::uint32_t> spirv(Stage stage, ShaderBuild build);

// GLSL 330 core; each specialization constant n is a macro
// SPIRV_CROSS_CONSTANT_ID_n with the shader's default unless defined first.
std::string_view glsl330(Stage stage, ShaderBuild build);

}  // namespace shaders
