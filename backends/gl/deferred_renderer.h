// The deferred path on OpenGL (SPEC 3.7, docs/model.md), three passes per
// frame:
//   G-buffer:  the scene's objects (scene_draws.h, as forward draws them)
//              into the G-buffer (gbuffer_targets.h), opaque-surface state;
//   light:     one draw per lighting::lightVolumes entry into the light
//              buffer, its GpuDeferredLightBlock bound per draw, with the
//              model's blend and raster state per volume (raster_state_gl.h
//              applies lighting::lightBufferState and
//              lighting::lightVolumeRasterState);
//   composite: a full-screen triangle into the backend's output framebuffer,
//              so readback does not know which path drew.
#pragma once

#include "backends/gl/baked_textures.h"
#include "backends/gl/deferred_programs.h"
#include "backends/gl/gbuffer_targets.h"
#include "backends/gl/gl_objects.h"
#include "backends/gl/scene_draws.h"
#include "lighting/deferred_lights.h"
#include "lighting/frame.h"
#include "shaders/shader_variant.h"

#include <vector>

namespace backends::gl {

class DeferredRenderer {
 public:
  DeferredRenderer(const GlFunctions& gl, const shaders::ShaderVariant& variant);

  // Links the programs for a frame drawn with its `constants` and light
  // `volumes` (lighting::lightVolumes; preparePipeline, and draw on demand):
  // a light program per volume, looking up that light's texture slots alone.
  DeferredProgramSet programs(const std::vector<lighting::LightVolume>& volumes,
                              const shaders::ConstantValues& constants);

  // Everything before the timed draws: the targets, the light volumes and
  // the deferred uniform blocks; leaves the G-buffer bound and cleared.
  void beginFrame(const lighting::Frame& frame, const std::vector<lighting::LightVolume>& volumes, int width,
                  int height);
  // The three passes, the last into `outputFramebuffer`.
  void drawFrame(const DeferredProgramSet& programs, const SceneDraws& scene, const BakedTextures& baked,
                 GLuint outputFramebuffer);

 private:
  struct VolumeDraw {
    lighting::LightVolumeShape shape;
    GLint firstVertex;
    GLsizei vertexCount;
  };

  void uploadVolumes(const lighting::Frame& frame, const std::vector<lighting::LightVolume>& volumes);
  void drawGbuffer(GLuint program, const SceneDraws& scene, const BakedTextures& baked);
  void drawLights(const std::vector<GLuint>& programs, const SceneDraws& scene);
  void drawComposite(GLuint program, GLuint outputFramebuffer);
  void bindGbufferTextures() const;
  void unbindDeferredTextures() const;

  const GlFunctions& gl_;
  shaders::ShaderVariant variant_;
  lighting::VolumeRule volumeRule_;
  DeferredPrograms programs_;
  GbufferTargets targets_;
  GlName volumeArray_, volumeVertices_;
  // The composite's triangle comes from gl_VertexID; GL core draws still
  // need a vertex array bound, so it gets one without attributes.
  GlName emptyArray_;
  GlName lightUniforms_, frameUniforms_;
  std::size_t lightStride_ = 0;
  std::vector<VolumeDraw> draws_;
  lighting::DeferredBuffer buffer_ = lighting::DeferredBuffer::Hdr32;
  int width_ = 0, height_ = 0;
};

}  // namespace backends::gl
