// RAII for GL object names: each owns one name and deletes it with the
// function given, while the context that made it is still current (the
// backend declares its objects after its context, so they go first).
#pragma once

#include "backends/gl/gl_functions.h"

#include <cstddef>
#include <functional>
#include <utility>

namespace backends::gl {

class GlName {
 public:
  GlName() = default;
  GlName(GLuint name, std::function<void(GLuint)> destroy) : name_(name), destroy_(std::move(destroy)) {}
  ~GlName() { reset(); }
  GlName(GlName&& other) noexcept : name_(std::exchange(other.name_, 0)), destroy_(std::move(other.destroy_)) {}
  GlName& operator=(GlName&& other) noexcept {
    if (this != &other) {
      reset();
      name_ = std::exchange(other.name_, 0);
      destroy_ = std::move(other.destroy_);
    }
    return *this;
  }
  GlName(const GlName&) = delete;
  GlName& operator=(const GlName&) = delete;

  GLuint get() const { return name_; }
  void reset() {
    if (name_ && destroy_) destroy_(name_);
    name_ = 0;
  }

 private:
  GLuint name_ = 0;
  std::function<void(GLuint)> destroy_;
};

// One object of each kind the renderer uses.
GlName makeBuffer(const GlFunctions& gl);
GlName makeVertexArray(const GlFunctions& gl);
GlName makeFramebuffer(const GlFunctions& gl);
GlName makeRenderbuffer(const GlFunctions& gl);
GlName makeQuery(const GlFunctions& gl);
GlName makeTexture(const GlFunctions& gl);

// The distance between blocks of one uniform buffer bound with
// glBindBufferRange: `blockSize` rounded up to the driver's
// GL_UNIFORM_BUFFER_OFFSET_ALIGNMENT (backends/aligned_stride.h).
std::size_t uniformBlockStride(const GlFunctions& gl, std::size_t blockSize);

// For the texture bound now to `target`: one level (complete without
// mipmaps), min and mag filter `filter` (GL_LINEAR for the baked maps and
// cookies, GL_NEAREST for render targets read with texelFetch), `wrap` on S,
// T and R (clamp to edge but for the tiled directional cookies).
void setSingleLevelSampling(const GlFunctions& gl, GLint filter, GLenum target = GL_TEXTURE_2D,
                            GLint wrap = GL_CLAMP_TO_EDGE);

}  // namespace backends::gl
