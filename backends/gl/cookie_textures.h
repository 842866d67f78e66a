// The light cookies of SPEC 3.10 as OpenGL textures (shaders/cookies.glsl):
// every cookie of a prepared scene uploaded once as R32F, its value
// (backends/cookie_texels.h), one level, LINEAR; 2D cookies repeat
// (directional) or clamp to edge (spot), cubes are seamless
// (GL_TEXTURE_CUBE_MAP_SEAMLESS, on for the backend's context). Each frame
// writes the lighting::GpuCookieBlock and binds the slots' textures to their
// units, the same units for every program that lights.
#pragma once

#include "backends/gl/gl_objects.h"
#include "lighting/cookie_slots.h"
#include "lighting/frame.h"

#include <memory>
#include <vector>

namespace backends::gl {

// Points `program`'s CookieBlock and cookie samplers at their binding point
// and units (shaders/shader_interface.def: the 2D slots, then the cube slots,
// each sampler on its own unit); needs `program` current. What a specialised
// program does not use is skipped.
void bindCookieInterface(const GlFunctions& gl, GLuint program);

class CookieTextures {
 public:
  // Turns GL_TEXTURE_CUBE_MAP_SEAMLESS on; needs the backend's context current.
  explicit CookieTextures(const GlFunctions& gl);

  // Uploads the cookies when the prepared scene is new (NotSupportedError
  // when one is larger than the driver allows), writes the frame's block and
  // binds it and the slots' textures for the draws that follow.
  void update(const lighting::Frame& frame);
  // Wall time of the last scene's upload (0 for a scene without cookies).
  double uploadMilliseconds() const { return uploadMilliseconds_; }

 private:
  void upload(const std::shared_ptr<const lighting::PreparedScene>& prepared);

  const GlFunctions& gl_;
  GLint maxSize_ = 0, maxCubeSize_ = 0;
  GlName block_;
  std::shared_ptr<const lighting::PreparedScene> scene_;
  std::vector<GlName> textures_;  // per scene light: its cookie, 0 without one
  double uploadMilliseconds_ = 0;
};

}  // namespace backends::gl
