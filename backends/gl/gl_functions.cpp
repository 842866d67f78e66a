#include "backends/gl/gl_functions.h"

#include "backends/backend.h"

#include <string>

namespace backends::gl {
namespace {

std::string errorName(GLenum error) {
  switch (error) {
    case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
    default: return "GL error " + std::to_string(error);
  }
}

}  // namespace

GlFunctions GlFunctions::load(const std::function<void*(const char*)>& getProcAddress) {
  GlFunctions f;
#define LIGHTCTS_GL_LOAD(type, name)                                                   \
  f.name = reinterpret_cast<type>(getProcAddress(#name));                              \
  if (!f.name) throw NotSupportedError("the GL context has no " #name);
  LIGHTCTS_GL_FUNCTIONS(LIGHTCTS_GL_LOAD)
#undef LIGHTCTS_GL_LOAD
#define LIGHTCTS_GL_LOAD_OPTIONAL(type, name) f.name = reinterpret_cast<type>(getProcAddress(#name));
  LIGHTCTS_GL_OPTIONAL_FUNCTIONS(LIGHTCTS_GL_LOAD_OPTIONAL)
#undef LIGHTCTS_GL_LOAD_OPTIONAL
  return f;
}

void GlFunctions::check(const char* when) const {
  std::string errors;
  // glGetError returns one recorded error per call; drain them all.
  for (GLenum e = glGetError(); e != GL_NO_ERROR; e = glGetError()) errors += (errors.empty() ? "" : ", ") + errorName(e);
  if (!errors.empty()) throw DriverError(std::string("OpenGL reported ") + errors + " while " + when);
}

}  // namespace backends::gl
