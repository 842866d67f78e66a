#include "backends/gl/program_builder.h"

#include "backends/backend.h"

#include <algorithm>
#include <vector>

namespace backends::gl {
namespace {

// The stage's source with the constants defined right after its #version line.
std::string specialise(std::string_view source, const shaders::ConstantValues& constants) {
  const std::size_t lineEnd = source.find('\n');
  std::string out(source.substr(0, lineEnd + 1));
  for (std::size_t id = 0; id < constants.size(); ++id) {
    // Booleans stay booleans: GLSL has no implicit int-to-bool conversion.
    const bool isBool = !shaders::constantIsInteger(std::uint32_t(id));
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

GlName compile(const GlFunctions& gl, GLenum stage, const std::string& source, const std::string& what) {
  GlName shader(gl.glCreateShader(stage), [&gl](GLuint n) { gl.glDeleteShader(n); });
  const char* text = source.c_str();
  gl.glShaderSource(shader.get(), 1, &text, nullptr);
  gl.glCompileShader(shader.get());
  GLint ok = GL_FALSE;
  gl.glGetShaderiv(shader.get(), GL_COMPILE_STATUS, &ok);
  if (!ok)
    throw DriverError("the GL driver rejected the " + what +
                      " shader: " + infoLog(gl.glGetShaderiv, gl.glGetShaderInfoLog, shader.get()));
  return shader;
}

}  // namespace

GlName linkProgram(const GlFunctions& gl, shaders::Stage vertexStage, shaders::Stage fragmentStage,
                   const shaders::ConstantValues& constants, const std::string& what) {
  const shaders::ShaderBuild build = shaders::shaderBuildOf(constants);
  const GlName vertex =
      compile(gl, GL_VERTEX_SHADER, specialise(shaders::glsl330(vertexStage, build), constants), what + "'s vertex");
  const GlName fragment = compile(gl, GL_FRAGMENT_SHADER, specialise(shaders::glsl330(fragmentStage, build), constants),
                                  what + "'s fragment");
  GlName program(gl.glCreateProgram(), [&gl](GLuint n) { gl.glDeleteProgram(n); });
  gl.glAttachShader(program.get(), vertex.get());
  gl.glAttachShader(program.get(), fragment.get());
  gl.glLinkProgram(program.get());
  GLint ok = GL_FALSE;
  gl.glGetProgramiv(program.get(), GL_LINK_STATUS, &ok);
  if (!ok)
    throw DriverError("the GL driver could not link " + what + ": " +
                      infoLog(gl.glGetProgramiv, gl.glGetProgramInfoLog, program.get()));
  return program;
}

void bindUniformBlock(const GlFunctions& gl, GLuint program, const shaders::binding::UniformBlock& block) {
  const GLuint index = gl.glGetUniformBlockIndex(program, block.name);
  if (index != GL_INVALID_INDEX) gl.glUniformBlockBinding(program, index, block.glBinding);
}

void bindSamplers(const GlFunctions& gl, GLuint program, const shaders::binding::Texture& texture) {
  for (std::size_t i = 0; i < texture.count(); ++i) {
    const GLint location = gl.glGetUniformLocation(program, texture.name(i));
    if (location != -1) gl.glUniform1i(location, texture.glUnit(i));
  }
}

}  // namespace backends::gl
