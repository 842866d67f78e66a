#include "backends/gl/forward_programs.h"

#include "backends/backend.h"
#include "shaders/embedded_spirv.h"

#include <algorithm>
#include <string>
#include <vector>

namespace backends::gl {
namespace {

// The stage's source with the constants defined right after its #version line.
std::string specialise(std::string_view source, const shaders::ConstantValues& constants) {
  const std::size_t lineEnd = source.find('\n');
  std::string out(source.substr(0, lineEnd + 1));
  for (std::size_t id = 0; id < constants.size(); ++id) {
    // Booleans stay booleans: GLSL has no implicit int-to-bool conversion.
    const bool isBool = id != shaders::kMutant;
    const std::string value = isBool ? (constants[id] ? "true" : "false") : std::to_string(constants[id]);
    out += "#define SPIRV_CROSS_CONSTANT_ID_" + std::to_string(id) + " " + value + "\n";
  }
  out += source.substr(lineEnd + 1);
  return out;
}

// The info log of a shader or program (glGetShaderiv/InfoLog or glGetProgramiv/InfoLog).
template <class GetInteger, class GetLog>
std::string infoLog(GetInteger getInteger, GetLog getLog, GLuint name) {
  GLint length = 0;
  getInteger(name, GL_INFO_LOG_LENGTH, &length);
  std::vector<char> log(std::size_t(std::max(length, 1)));
  getLog(name, GLsizei(log.size()), nullptr, log.data());
  return log.data();
}

}  // namespace

GLuint ForwardPrograms::program(const shaders::ConstantValues& constants) {
  auto found = programs_.find(constants);
  if (found == programs_.end()) found = programs_.emplace(constants, build(constants)).first;
  return found->second.get();
}

GlName ForwardPrograms::compile(GLenum stage, const std::string& source, const char* what) const {
  GlName shader(gl_.glCreateShader(stage), [this](GLuint n) { gl_.glDeleteShader(n); });
  const char* text = source.c_str();
  gl_.glShaderSource(shader.get(), 1, &text, nullptr);
  gl_.glCompileShader(shader.get());
  GLint ok = GL_FALSE;
  gl_.glGetShaderiv(shader.get(), GL_COMPILE_STATUS, &ok);
  if (!ok)
    throw DriverError(std::string("the GL driver rejected the ") + what +
                      " shader: " + infoLog(gl_.glGetShaderiv, gl_.glGetShaderInfoLog, shader.get()));
  return shader;
}

GlName ForwardPrograms::build(const shaders::ConstantValues& constants) const {
  const GlName vertex = compile(GL_VERTEX_SHADER, specialise(shaders::forwardVertexGlsl330(), constants), "vertex");
  const GlName fragment =
      compile(GL_FRAGMENT_SHADER, specialise(shaders::forwardFragmentGlsl330(), constants), "fragment");
  GlName program(gl_.glCreateProgram(), [this](GLuint n) { gl_.glDeleteProgram(n); });
  gl_.glAttachShader(program.get(), vertex.get());
  gl_.glAttachShader(program.get(), fragment.get());
  gl_.glLinkProgram(program.get());
  GLint ok = GL_FALSE;
  gl_.glGetProgramiv(program.get(), GL_LINK_STATUS, &ok);
  if (!ok)
    throw DriverError("the GL driver could not link the forward program: " +
                      infoLog(gl_.glGetProgramiv, gl_.glGetProgramInfoLog, program.get()));
  // A block the specialised shader does not use has no index; that is fine.
  const GLuint frameBlock = gl_.glGetUniformBlockIndex(program.get(), "FrameBlock");
  if (frameBlock != GL_INVALID_INDEX) gl_.glUniformBlockBinding(program.get(), frameBlock, kFrameBlockBinding);
  const GLuint objectBlock = gl_.glGetUniformBlockIndex(program.get(), "ObjectBlock");
  if (objectBlock != GL_INVALID_INDEX) gl_.glUniformBlockBinding(program.get(), objectBlock, kObjectBlockBinding);
  // GLSL 330 has no binding qualifiers: the samplers get their units here,
  // once. A sampler the specialised shader does not use has location -1.
  gl_.glUseProgram(program.get());
  const GLint lightmap = gl_.glGetUniformLocation(program.get(), "lightmapTexture");
  if (lightmap != -1) gl_.glUniform1i(lightmap, kLightmapTextureUnit);
  const GLint shadowMask = gl_.glGetUniformLocation(program.get(), "shadowMaskTexture");
  if (shadowMask != -1) gl_.glUniform1i(shadowMask, kShadowMaskTextureUnit);
  gl_.glUseProgram(0);
  gl_.check("linking the forward program");
  return program;
}

}  // namespace backends::gl
