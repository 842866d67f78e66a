#include "backends/gl/forward_programs.h"

#include "backends/gl/cluster_lists.h"
#include "backends/gl/cookie_textures.h"
#include "backends/gl/program_builder.h"
#include "backends/gl/shadow_maps.h"
#include "shaders/embedded_spirv.h"

namespace backends::gl {

GLuint ForwardPrograms::program(const shaders::ConstantValues& constants) {
  auto found = programs_.find(constants);
  if (found == programs_.end()) found = programs_.emplace(constants, build(constants)).first;
  return found->second.get();
}

void bindSceneObjectInterface(const GlFunctions& gl, GLuint program) {
  bindUniformBlock(gl, program, shaders::binding::kFrameBlock);
  bindUniformBlock(gl, program, shaders::binding::kObjectBlock);
  // The samplers get their units once, with the program current.
  gl.glUseProgram(program);
  bindSamplers(gl, program, shaders::binding::kLightmapTexture);
  bindSamplers(gl, program, shaders::binding::kShadowMaskTexture);
  bindCookieInterface(gl, program);
  bindShadowInterface(gl, program);
}

GlName ForwardPrograms::build(const shaders::ConstantValues& constants) const {
  GlName program = linkProgram(gl_, shaders::Stage::ForwardVertex, shaders::Stage::ForwardFragment, constants,
                               "the forward program");
  bindSceneObjectInterface(gl_, program.get());
  bindClusterListsInterface(gl_, program.get());  // forward only: the G-buffer pass has no clusters
  gl_.glUseProgram(0);
  gl_.check("linking the forward program");
  return program;
}

}  // namespace backends::gl
