// The scene's objects as OpenGL draws, shared by the forward pass and the
// deferred G-buffer pass (which uses forward's vertex stage): the geometry in
// one vertex and one index buffer, the frame block in one uniform buffer and
// the object blocks in another at the driver's offset alignment, bound per
// draw with glBindBufferRange together with the object's baked maps.
#pragma once

#include "backends/gl/baked_textures.h"
#include "backends/gl/gl_objects.h"
#include "backends/packed_geometry.h"
#include "lighting/frame.h"
#include "lighting/gpu_packing.h"

#include <memory>
#include <vector>

namespace backends::gl {

class SceneDraws {
 public:
  // `grid`: the device's bits, for the admissible variants (lighting::DeviceGrid).
  SceneDraws(const GlFunctions& gl, const lighting::DeviceGrid& grid) : gl_(gl), grid_(grid) {}

  // Uploads the geometry when the scene changed, and the frame's uniforms.
  void update(const lighting::Frame& frame);
  // Binds the frame block to its binding point (shaders/shader_interface.def).
  void bindFrameBlock() const;
  // Draws every object with the current program and framebuffer state.
  void drawObjects(const BakedTextures& baked) const;
  // The same draws without the baked maps, for a program that samples none
  // (the shadow-caster pass): only the frame and object blocks are bound.
  void drawGeometry() const;

 private:
  void uploadGeometry(const lighting::Frame& frame);
  void writeUniforms(const lighting::Frame& frame);
  void draw(const BakedTextures* baked) const;  // binds `baked`'s maps per object unless null

  const GlFunctions& gl_;
  lighting::DeviceGrid grid_;
  GlName vertexArray_, vertices_, indices_;
  GlName frameUniforms_, objectUniforms_;
  std::size_t objectStride_ = 0;
  std::vector<ObjectRange> objects_;
  std::shared_ptr<const lighting::PreparedScene> scene_;
};

}  // namespace backends::gl
