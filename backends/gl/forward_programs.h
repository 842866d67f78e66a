// The forward program for OpenGL (program_builder.h makes it from the GLSL
// 330 of the Vulkan SPIR-V). One program per set of constants, linked on
// first use; the uniform blocks (frame, object) and the baked maps' samplers
// are bound by name to the binding points and texture units of
// shaders/shader_interface.def, the cookies' and shadow maps' as
// cookie_textures.h and shadow_maps.h bind them, the clustered mode's lists
// as cluster_lists.h does.
#pragma once

#include "backends/gl/gl_objects.h"
#include "shaders/shader_constants.h"

#include <map>

namespace backends::gl {

// The uniform blocks and samplers of every program that draws the scene's
// objects through forward.vert (the forward program, the deferred G-buffer
// program). Leaves `program` current.
void bindSceneObjectInterface(const GlFunctions& gl, GLuint program);

class ForwardPrograms {
 public:
  explicit ForwardPrograms(const GlFunctions& gl) : gl_(gl) {}
  // The program for `constants`; throws DriverError with the compiler's log.
  GLuint program(const shaders::ConstantValues& constants);

 private:
  GlName build(const shaders::ConstantValues& constants) const;

  const GlFunctions& gl_;
  std::map<shaders::ConstantValues, GlName> programs_;
};

}  // namespace backends::gl
