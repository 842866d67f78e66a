#include "backends/gl/deferred_renderer.h"

#include "backends/gl/forward_programs.h"
#include "backends/gl/raster_state_gl.h"
#include "shaders/gbuffer_textures.h"

#include <algorithm>
#include <cstring>

namespace backends::gl {

DeferredRenderer::DeferredRenderer(const GlFunctions& gl, const shaders::ShaderVariant& variant)
    : gl_(gl), variant_(variant), volumeRule_(shaders::volumeRule(variant.mutant)), programs_(gl), targets_(gl) {
  volumeArray_ = makeVertexArray(gl_);
  emptyArray_ = makeVertexArray(gl_);
  volumeVertices_ = makeBuffer(gl_);
  lightUniforms_ = makeBuffer(gl_);
  frameUniforms_ = makeBuffer(gl_);
  lightStride_ = uniformBlockStride(gl_, sizeof(lighting::GpuDeferredLightBlock));
  // deferred_light.vert's location 0: a vec4 position per vertex.
  gl_.glBindVertexArray(volumeArray_.get());
  gl_.glBindBuffer(GL_ARRAY_BUFFER, volumeVertices_.get());
  gl_.glEnableVertexAttribArray(0);
  gl_.glVertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, sizeof(lighting::GpuVec4), nullptr);
  gl_.glBindVertexArray(0);
  gl_.check("creating the deferred renderer's buffers");
}

DeferredProgramSet DeferredRenderer::programs(const std::vector<lighting::LightVolume>& volumes,
                                              const shaders::ConstantValues& constants) {
  std::vector<shaders::ConstantValues> lights;
  for (const lighting::LightVolume& volume : volumes)
    lights.push_back(shaders::lightPassConstants(constants, volume.slots, variant_));
  return programs_.programs(constants, lights);
}

void DeferredRenderer::beginFrame(const lighting::Frame& frame, const std::vector<lighting::LightVolume>& volumes,
                                  int width, int height) {
  buffer_ = frame.scene().pipeline.deferredBuffer;
  width_ = width;
  height_ = height;
  targets_.ensure(width, height, buffer_);
  uploadVolumes(frame, volumes);
  const lighting::GpuDeferredFrameBlock block = lighting::packDeferredFrame(frame);
  gl_.glBindBuffer(GL_UNIFORM_BUFFER, frameUniforms_.get());
  gl_.glBufferData(GL_UNIFORM_BUFFER, sizeof(block), &block, GL_DYNAMIC_DRAW);
  gl_.glBindBuffer(GL_UNIFORM_BUFFER, 0);

  gl_.glBindFramebuffer(GL_FRAMEBUFFER, targets_.gbufferFramebuffer());
  gl_.glViewport(0, 0, width_, height_);
  // A clear honours the depth mask, which the light pass turns off.
  gl_.glDepthMask(GL_TRUE);
  for (int t = 0; t < kGbufferColourCount; ++t) gl_.glClearBufferfv(GL_COLOR, t, lighting::kGbufferClear.data());
  gl_.glClearBufferfv(GL_DEPTH, 0, &lighting::kClearDepth);
  gl_.check("preparing the deferred frame");
}

void DeferredRenderer::drawFrame(const DeferredProgramSet& programs, const SceneDraws& scene,
                                 const BakedTextures& baked, GLuint outputFramebuffer) {
  drawGbuffer(programs.gbuffer, scene, baked);
  drawLights(programs.lights, scene);
  drawComposite(programs.composite, outputFramebuffer);
  unbindDeferredTextures();
}

void DeferredRenderer::uploadVolumes(const lighting::Frame& frame, const std::vector<lighting::LightVolume>& volumes) {
  std::vector<lighting::GpuVec4> vertices;
  std::vector<unsigned char> blocks(std::max<std::size_t>(volumes.size(), 1) * lightStride_);
  draws_.clear();
  for (std::size_t v = 0; v < volumes.size(); ++v) {
    const lighting::LightVolume& volume = volumes[v];
    draws_.push_back({volume.shape, GLint(vertices.size()), GLsizei(volume.vertices.size())});
    vertices.insert(vertices.end(), volume.vertices.begin(), volume.vertices.end());
    const lighting::GpuDeferredLightBlock block = lighting::packDeferredLight(frame, volume.light);
    std::memcpy(&blocks[v * lightStride_], &block, sizeof(block));
  }
  gl_.glBindBuffer(GL_ARRAY_BUFFER, volumeVertices_.get());
  gl_.glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(lighting::GpuVec4)), vertices.data(),
                   GL_DYNAMIC_DRAW);
  gl_.glBindBuffer(GL_ARRAY_BUFFER, 0);
  gl_.glBindBuffer(GL_UNIFORM_BUFFER, lightUniforms_.get());
  gl_.glBufferData(GL_UNIFORM_BUFFER, GLsizeiptr(blocks.size()), blocks.data(), GL_DYNAMIC_DRAW);
  gl_.glBindBuffer(GL_UNIFORM_BUFFER, 0);
  gl_.check("uploading the light volumes");
}

void DeferredRenderer::drawGbuffer(GLuint program, const SceneDraws& scene, const BakedTextures& baked) {
  gl_.glBindFramebuffer(GL_FRAMEBUFFER, targets_.gbufferFramebuffer());
  gl_.glViewport(0, 0, width_, height_);
  applyOpaqueSurfaceState(gl_);  // SPEC 1, as forward
  gl_.glUseProgram(program);
  scene.drawObjects(baked);
}

// Each volume with the model's raster state (lighting::lightVolumeRasterState:
// back faces behind or on the G-buffer's surface, which a ray through a pixel
// meets exactly once, also with the camera inside), blended into the light
// buffer from the blend's identity (lighting::lightBufferState).
void DeferredRenderer::drawLights(const std::vector<GLuint>& programs, const SceneDraws& scene) {
  const lighting::LightBufferState buffer = lighting::lightBufferState(buffer_);
  const float clear[4] = {buffer.clearValue, buffer.clearValue, buffer.clearValue, buffer.clearValue};
  gl_.glBindFramebuffer(GL_FRAMEBUFFER, targets_.lightFramebuffer());
  gl_.glViewport(0, 0, width_, height_);
  gl_.glClearBufferfv(GL_COLOR, 0, clear);
  applyLightBlend(gl_, buffer.blend);
  gl_.glBindVertexArray(volumeArray_.get());
  scene.bindFrameBlock();
  gl_.glBindBufferRange(GL_UNIFORM_BUFFER, shaders::binding::kDeferredFrameBlock.glBinding, frameUniforms_.get(), 0,
                        sizeof(lighting::GpuDeferredFrameBlock));
  bindGbufferTextures();
  GLuint bound = 0;
  for (std::size_t d = 0; d < draws_.size(); ++d) {
    if (draws_[d].vertexCount == 0) continue;
    if (programs.at(d) != bound) gl_.glUseProgram(bound = programs[d]);  // the light's own slots
    gl_.glBindBufferRange(GL_UNIFORM_BUFFER, shaders::binding::kDeferredLightBlock.glBinding, lightUniforms_.get(),
                          GLintptr(d * lightStride_), sizeof(lighting::GpuDeferredLightBlock));
    applyRasterState(gl_, lighting::lightVolumeRasterState(draws_[d].shape, volumeRule_));
    gl_.glDrawArrays(GL_TRIANGLES, draws_[d].firstVertex, draws_[d].vertexCount);
  }
  gl_.glBindVertexArray(0);
}

void DeferredRenderer::drawComposite(GLuint program, GLuint outputFramebuffer) {
  gl_.glBindFramebuffer(GL_FRAMEBUFFER, outputFramebuffer);
  gl_.glViewport(0, 0, width_, height_);
  gl_.glDisable(GL_DEPTH_TEST);
  gl_.glDisable(GL_CULL_FACE);
  gl_.glDisable(GL_BLEND);
  gl_.glUseProgram(program);
  gl_.glBindBufferRange(GL_UNIFORM_BUFFER, shaders::binding::kDeferredFrameBlock.glBinding, frameUniforms_.get(), 0,
                        sizeof(lighting::GpuDeferredFrameBlock));
  gl_.glActiveTexture(GL_TEXTURE0 + shaders::binding::kLightBuffer.glUnit());
  gl_.glBindTexture(GL_TEXTURE_2D, targets_.lightBuffer());
  gl_.glBindVertexArray(emptyArray_.get());
  gl_.glDrawArrays(GL_TRIANGLES, 0, 3);
  gl_.glBindVertexArray(0);
}

void DeferredRenderer::bindGbufferTextures() const {
  for (int t = 0; t < kGbufferColourCount; ++t) {
    gl_.glActiveTexture(GLenum(GL_TEXTURE0 + shaders::kGbufferTextures[t].glUnit()));
    gl_.glBindTexture(GL_TEXTURE_2D, targets_.texture(GbufferTexture(t)));
  }
}

// No target stays bound to a texture unit while the next frame renders into
// it: GL leaves such a feedback loop undefined once a program samples it.
void DeferredRenderer::unbindDeferredTextures() const {
  for (const shaders::binding::Texture& texture : shaders::kGbufferTextures) {
    gl_.glActiveTexture(GLenum(GL_TEXTURE0 + texture.glUnit()));
    gl_.glBindTexture(GL_TEXTURE_2D, 0);
  }
  gl_.glActiveTexture(GLenum(GL_TEXTURE0 + shaders::binding::kLightBuffer.glUnit()));
  gl_.glBindTexture(GL_TEXTURE_2D, 0);
  gl_.glActiveTexture(GL_TEXTURE0);
}

}  // namespace backends::gl
