// The one GL function loader: every GL entry point the renderer calls, as a
// pointer filled from the context API's proc-address function
// (eglGetProcAddress or OSMesaGetProcAddress). Nothing else in the backend
// casts a function pointer.
#pragma once

#include <GL/glcorearb.h>

#include <functional>

namespace backends::gl {

// X-macro: (type of the pointer, name).
#define LIGHTCTS_GL_FUNCTIONS(X)                                   \
  X(PFNGLGETERRORPROC, glGetError)                                 \
  X(PFNGLGETSTRINGPROC, glGetString)                               \
  X(PFNGLGETINTEGERVPROC, glGetIntegerv)                           \
  X(PFNGLCREATESHADERPROC, glCreateShader)                         \
  X(PFNGLSHADERSOURCEPROC, glShaderSource)                         \
  X(PFNGLCOMPILESHADERPROC, glCompileShader)                       \
  X(PFNGLGETSHADERIVPROC, glGetShaderiv)                           \
  X(PFNGLGETSHADERINFOLOGPROC, glGetShaderInfoLog)                 \
  X(PFNGLDELETESHADERPROC, glDeleteShader)                         \
  X(PFNGLCREATEPROGRAMPROC, glCreateProgram)                       \
  X(PFNGLATTACHSHADERPROC, glAttachShader)                         \
  X(PFNGLLINKPROGRAMPROC, glLinkProgram)                           \
  X(PFNGLGETPROGRAMIVPROC, glGetProgramiv)                         \
  X(PFNGLGETPROGRAMINFOLOGPROC, glGetProgramInfoLog)               \
  X(PFNGLDELETEPROGRAMPROC, glDeleteProgram)                       \
  X(PFNGLUSEPROGRAMPROC, glUseProgram)                             \
  X(PFNGLGETUNIFORMBLOCKINDEXPROC, glGetUniformBlockIndex)         \
  X(PFNGLUNIFORMBLOCKBINDINGPROC, glUniformBlockBinding)           \
  X(PFNGLGENBUFFERSPROC, glGenBuffers)                             \
  X(PFNGLDELETEBUFFERSPROC, glDeleteBuffers)                       \
  X(PFNGLBINDBUFFERPROC, glBindBuffer)                             \
  X(PFNGLBUFFERDATAPROC, glBufferData)                             \
  X(PFNGLBUFFERSUBDATAPROC, glBufferSubData)                       \
  X(PFNGLBINDBUFFERRANGEPROC, glBindBufferRange)                   \
  X(PFNGLGENVERTEXARRAYSPROC, glGenVertexArrays)                   \
  X(PFNGLDELETEVERTEXARRAYSPROC, glDeleteVertexArrays)             \
  X(PFNGLBINDVERTEXARRAYPROC, glBindVertexArray)                   \
  X(PFNGLENABLEVERTEXATTRIBARRAYPROC, glEnableVertexAttribArray)   \
  X(PFNGLVERTEXATTRIBPOINTERPROC, glVertexAttribPointer)           \
  X(PFNGLGENFRAMEBUFFERSPROC, glGenFramebuffers)                   \
  X(PFNGLDELETEFRAMEBUFFERSPROC, glDeleteFramebuffers)             \
  X(PFNGLBINDFRAMEBUFFERPROC, glBindFramebuffer)                   \
  X(PFNGLFRAMEBUFFERRENDERBUFFERPROC, glFramebufferRenderbuffer)   \
  X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, glCheckFramebufferStatus)     \
  X(PFNGLGENRENDERBUFFERSPROC, glGenRenderbuffers)                 \
  X(PFNGLDELETERENDERBUFFERSPROC, glDeleteRenderbuffers)           \
  X(PFNGLBINDRENDERBUFFERPROC, glBindRenderbuffer)                 \
  X(PFNGLRENDERBUFFERSTORAGEPROC, glRenderbufferStorage)           \
  X(PFNGLDRAWBUFFERSPROC, glDrawBuffers)                           \
  X(PFNGLREADBUFFERPROC, glReadBuffer)                             \
  X(PFNGLVIEWPORTPROC, glViewport)                                 \
  X(PFNGLENABLEPROC, glEnable)                                     \
  X(PFNGLDISABLEPROC, glDisable)                                   \
  X(PFNGLDEPTHFUNCPROC, glDepthFunc)                               \
  X(PFNGLDEPTHMASKPROC, glDepthMask)                               \
  X(PFNGLCULLFACEPROC, glCullFace)                                 \
  X(PFNGLFRONTFACEPROC, glFrontFace)                               \
  X(PFNGLCLEARBUFFERFVPROC, glClearBufferfv)                       \
  X(PFNGLDRAWELEMENTSBASEVERTEXPROC, glDrawElementsBaseVertex)     \
  X(PFNGLPIXELSTOREIPROC, glPixelStorei)                           \
  X(PFNGLREADPIXELSPROC, glReadPixels)                             \
  X(PFNGLFINISHPROC, glFinish)                                     \
  X(PFNGLGENQUERIESPROC, glGenQueries)                             \
  X(PFNGLDELETEQUERIESPROC, glDeleteQueries)                       \
  X(PFNGLGETQUERYIVPROC, glGetQueryiv)                             \
  X(PFNGLBEGINQUERYPROC, glBeginQuery)                             \
  X(PFNGLENDQUERYPROC, glEndQuery)                                 \
  X(PFNGLGETQUERYOBJECTUI64VPROC, glGetQueryObjectui64v)           \
  X(PFNGLGETUNIFORMLOCATIONPROC, glGetUniformLocation)             \
  X(PFNGLUNIFORM1IPROC, glUniform1i)                               \
  X(PFNGLGENTEXTURESPROC, glGenTextures)                           \
  X(PFNGLDELETETEXTURESPROC, glDeleteTextures)                     \
  X(PFNGLBINDTEXTUREPROC, glBindTexture)                           \
  X(PFNGLACTIVETEXTUREPROC, glActiveTexture)                       \
  X(PFNGLTEXIMAGE2DPROC, glTexImage2D)                             \
  X(PFNGLTEXPARAMETERIPROC, glTexParameteri)                       \
  X(PFNGLTEXBUFFERPROC, glTexBuffer)                               \
  X(PFNGLFRAMEBUFFERTEXTURE2DPROC, glFramebufferTexture2D)         \
  X(PFNGLBLENDFUNCPROC, glBlendFunc)                               \
  X(PFNGLBLENDEQUATIONPROC, glBlendEquation)                       \
  X(PFNGLDRAWARRAYSPROC, glDrawArrays)

// Entry points of later GL versions than the 3.3 the backend needs: null when
// the library has none. Mesa hands out a pointer for every name it knows,
// whatever the context's version, so callers check the version before use.
// glGetInternalformativ: GL 4.2; its GL_FILTER query: GL 4.3.
#define LIGHTCTS_GL_OPTIONAL_FUNCTIONS(X) X(PFNGLGETINTERNALFORMATIVPROC, glGetInternalformativ)

struct GlFunctions {
#define LIGHTCTS_GL_MEMBER(type, name) type name = nullptr;
  LIGHTCTS_GL_FUNCTIONS(LIGHTCTS_GL_MEMBER)
  LIGHTCTS_GL_OPTIONAL_FUNCTIONS(LIGHTCTS_GL_MEMBER)
#undef LIGHTCTS_GL_MEMBER

  // Fills every pointer; throws NotSupportedError naming the first missing
  // required one (optional ones may stay null).
  static GlFunctions load(const std::function<void*(const char*)>& getProcAddress);

  // Throws DriverError naming `when` and the GL error, if glGetError has one.
  void check(const char* when) const;
};

}  // namespace backends::gl
