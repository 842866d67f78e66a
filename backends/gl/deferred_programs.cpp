#include "backends/gl/deferred_programs.h"

#include "backends/gl/cookie_textures.h"
#include "backends/gl/forward_programs.h"
#include "backends/gl/program_builder.h"
#include "backends/gl/shadow_maps.h"
#include "shaders/embedded_spirv.h"
#include "shaders/gbuffer_textures.h"

namespace backends::gl {

DeferredProgramSet DeferredPrograms::programs(const shaders::ConstantValues& constants,
                                              const std::vector<shaders::ConstantValues>& lightConstants) {
  auto found = programs_.find(constants);
  if (found == programs_.end()) found = programs_.emplace(constants, build(constants)).first;
  DeferredProgramSet set{found->second.gbuffer.get(), {}, found->second.composite.get()};
  for (const shaders::ConstantValues& light : lightConstants) {
    auto program = lights_.find(light);
    if (program == lights_.end()) {
      program = lights_.emplace(light, buildLight(light)).first;
      gl_.glUseProgram(0);
      gl_.check("linking a deferred light program");
    }
    set.lights.push_back(program->second.get());
  }
  return set;
}

DeferredPrograms::Linked DeferredPrograms::build(const shaders::ConstantValues& constants) const {
  Linked linked;
  linked.gbuffer = buildGbuffer(constants);
  linked.composite = buildComposite(constants);
  gl_.glUseProgram(0);
  gl_.check("linking the deferred programs");
  return linked;
}

GlName DeferredPrograms::buildGbuffer(const shaders::ConstantValues& constants) const {
  GlName program = linkProgram(gl_, shaders::Stage::ForwardVertex, shaders::Stage::GbufferFragment, constants,
                               "the deferred G-buffer program");
  bindSceneObjectInterface(gl_, program.get());  // as the forward program
  return program;
}

GlName DeferredPrograms::buildLight(const shaders::ConstantValues& constants) const {
  GlName program = linkProgram(gl_, shaders::Stage::DeferredLightVertex, shaders::Stage::DeferredLightFragment,
                               constants, "the deferred light program");
  bindUniformBlock(gl_, program.get(), shaders::binding::kFrameBlock);
  bindUniformBlock(gl_, program.get(), shaders::binding::kDeferredLightBlock);
  bindUniformBlock(gl_, program.get(), shaders::binding::kDeferredFrameBlock);
  gl_.glUseProgram(program.get());
  for (const shaders::binding::Texture& texture : shaders::kGbufferTextures) bindSamplers(gl_, program.get(), texture);
  bindCookieInterface(gl_, program.get());
  bindShadowInterface(gl_, program.get());  // SPEC 3.9: the light pass reads the maps
  return program;
}

GlName DeferredPrograms::buildComposite(const shaders::ConstantValues& constants) const {
  GlName program = linkProgram(gl_, shaders::Stage::DeferredCompositeVertex,
                               shaders::Stage::DeferredCompositeFragment, constants,
                               "the deferred composite program");
  bindUniformBlock(gl_, program.get(), shaders::binding::kDeferredFrameBlock);
  gl_.glUseProgram(program.get());
  for (const shaders::binding::Texture& texture : shaders::kGbufferTextures) bindSamplers(gl_, program.get(), texture);
  bindSamplers(gl_, program.get(), shaders::binding::kLightBuffer);
  return program;
}

}  // namespace backends::gl
