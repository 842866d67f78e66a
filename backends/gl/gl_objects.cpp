#include "backends/gl/gl_objects.h"

#include "backends/aligned_stride.h"

namespace backends::gl {
namespace {

// glGen* and glDelete* share one shape: (count, names).
template <class Generate, class Delete>
GlName makeName(const GlFunctions& gl, Generate generate, Delete destroy) {
  GLuint name = 0;
  (gl.*generate)(1, &name);
  return GlName(name, [&gl, destroy](GLuint n) { (gl.*destroy)(1, &n); });
}

}  // namespace

GlName makeBuffer(const GlFunctions& gl) {
  return makeName(gl, &GlFunctions::glGenBuffers, &GlFunctions::glDeleteBuffers);
}

GlName makeVertexArray(const GlFunctions& gl) {
  return makeName(gl, &GlFunctions::glGenVertexArrays, &GlFunctions::glDeleteVertexArrays);
}

GlName makeFramebuffer(const GlFunctions& gl) {
  return makeName(gl, &GlFunctions::glGenFramebuffers, &GlFunctions::glDeleteFramebuffers);
}

GlName makeRenderbuffer(const GlFunctions& gl) {
  return makeName(gl, &GlFunctions::glGenRenderbuffers, &GlFunctions::glDeleteRenderbuffers);
}

GlName makeQuery(const GlFunctions& gl) {
  return makeName(gl, &GlFunctions::glGenQueries, &GlFunctions::glDeleteQueries);
}

GlName makeTexture(const GlFunctions& gl) {
  return makeName(gl, &GlFunctions::glGenTextures, &GlFunctions::glDeleteTextures);
}

void setSingleLevelSampling(const GlFunctions& gl, GLint filter, GLenum target, GLint wrap) {
  gl.glTexParameteri(target, GL_TEXTURE_BASE_LEVEL, 0);
  gl.glTexParameteri(target, GL_TEXTURE_MAX_LEVEL, 0);
  gl.glTexParameteri(target, GL_TEXTURE_MIN_FILTER, filter);
  gl.glTexParameteri(target, GL_TEXTURE_MAG_FILTER, filter);
  gl.glTexParameteri(target, GL_TEXTURE_WRAP_S, wrap);
  gl.glTexParameteri(target, GL_TEXTURE_WRAP_T, wrap);
  gl.glTexParameteri(target, GL_TEXTURE_WRAP_R, wrap);
}

std::size_t uniformBlockStride(const GlFunctions& gl, std::size_t blockSize) {
  GLint alignment = 256;  // the largest alignment GL allows, should the query fail
  gl.glGetIntegerv(GL_UNIFORM_BUFFER_OFFSET_ALIGNMENT, &alignment);
  return alignedStride(blockSize, std::size_t(alignment));
}

}  // namespace backends::gl
