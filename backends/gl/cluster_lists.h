// The clustered mode's light lists (shaders/clusters.glsl) as an
// OpenGL 3.3 texture buffer of GL_R32UI texels on the unit of the forward
// program's `clusterLists` sampler (shaders/shader_interface.def). Every forward frame writes it:
// the frame's lists in the clustered mode, one zero texel otherwise, so the
// full shader's sampler always has a complete texture.
#pragma once

#include "backends/gl/gl_objects.h"
#include "backends/gl/shadow_maps.h"
#include "lighting/frame.h"

namespace backends::gl {

// Points `program`'s clusterLists sampler at its unit; needs
// `program` current. A program without it (specialised off) is skipped.
void bindClusterListsInterface(const GlFunctions& gl, GLuint program);

class ClusterLists {
 public:
  explicit ClusterLists(const GlFunctions& gl);

  // Uploads `frame`'s texels (lighting::packFrameClusterTexels) and binds the
  // texture to its unit; throws NotSupportedError past the driver's
  // GL_MAX_TEXTURE_BUFFER_SIZE.
  void update(const lighting::Frame& frame);

 private:
  const GlFunctions& gl_;
  GLint maxTexels_ = 0;
  GlName buffer_, texture_;
};

}  // namespace backends::gl
