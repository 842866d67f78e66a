// Compiling and linking the GLSL 330 that SPIRV-Cross made of the Vulkan
// SPIR-V (shaders/embedded_spirv.h), shared by the forward and the deferred
// programs. Each specialization constant is defined as the
// SPIRV_CROSS_CONSTANT_ID_n macro it became. GLSL 330 has no binding
// qualifiers, so uniform blocks and samplers are bound by name here, to the
// binding points and texture units of shaders/shader_interface.def.
#pragma once

#include "backends/gl/gl_objects.h"
#include "shaders/shader_constants.h"

#include <string>
#include <string_view>

namespace backends::gl {

// The program of two stages, in the build `constants` ask for
// (shaders::shaderBuildOf), with `constants` defined; throws DriverError with
// the compiler's or linker's log, naming `what` ("the forward program").
GlName linkProgram(const GlFunctions& gl, shaders::Stage vertexStage, shaders::Stage fragmentStage,
                   const shaders::ConstantValues& constants, const std::string& what);

// Binds the uniform block to its binding point (shaders/shader_interface.def);
// a block the specialised program does not use has no index, and is skipped.
void bindUniformBlock(const GlFunctions& gl, GLuint program, const shaders::binding::UniformBlock& block);

// Points each sampler of `texture` at its texture unit (shaders/shader_interface.def);
// needs `program` current. A sampler the specialised program does not use
// has location -1: skipped.
void bindSamplers(const GlFunctions& gl, GLuint program, const shaders::binding::Texture& texture);

}  // namespace backends::gl
