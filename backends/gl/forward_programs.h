// The forward program for OpenGL: the GLSL 330 that SPIRV-Cross made of the
// Vulkan SPIR-V (shaders/embedded_spirv.h), with each specialization
// constant defined as the SPIRV_CROSS_CONSTANT_ID_n macro it became. One
// program per set of constants, linked on first use; the uniform blocks are
// bound by name to the bindings the Vulkan layout uses (0 frame, 1 object),
// and the baked maps' samplers to texture units 0 (lightmap) and 1 (mask).
#pragma once

#include "backends/gl/gl_objects.h"
#include "shaders/shader_constants.h"

#include <map>

namespace backends::gl {

constexpr GLuint kFrameBlockBinding = 0;
constexpr GLuint kObjectBlockBinding = 1;
constexpr GLint kLightmapTextureUnit = 0;
constexpr GLint kShadowMaskTextureUnit = 1;

class ForwardPrograms {
 public:
  explicit ForwardPrograms(const GlFunctions& gl) : gl_(gl) {}
  // The program for `constants`; throws DriverError with the compiler's log.
  GLuint program(const shaders::ConstantValues& constants);

 private:
  GlName build(const shaders::ConstantValues& constants) const;
  GlName compile(GLenum stage, const std::string& source, const char* what) const;

  const GlFunctions& gl_;
  std::map<shaders::ConstantValues, GlName> programs_;
};

}  // namespace backends::gl
