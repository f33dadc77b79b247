#include "gpu/program.h"

#include <vector>

#include "shaders/shader_source.h"

namespace voxgi::gpu {
namespace {

GLenum stageType(std::string_view file) {
  if (file.ends_with(".vert")) return GL_VERTEX_SHADER;
  if (file.ends_with(".geom")) return GL_GEOMETRY_SHADER;
  if (file.ends_with(".frag")) return GL_FRAGMENT_SHADER;
  if (file.ends_with(".comp")) return GL_COMPUTE_SHADER;
  throw ShaderError(std::string(file) + ": unknown shader stage extension");
}

}  // namespace

GLuint compileShader(const Gl& gl, const ShaderSource& source, std::string_view text) {
  const GLuint shader = gl.CreateShader(stageType(source.name));
  const char* chars = text.data();
  const auto length = static_cast<GLint>(text.size());
  gl.ShaderSource(shader, 1, &chars, &length);
  gl.CompileShader(shader);
  GLint ok = 0;
  gl.GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok) return shader;
  GLint logLength = 0;
  gl.GetShaderiv(shader, GL_INFO_LOG_LENGTH, &logLength);
  std::vector<char> log(static_cast<size_t>(logLength) + 1, '\0');
  gl.GetShaderInfoLog(shader, logLength, nullptr, log.data());
  gl.DeleteShader(shader);
  throw ShaderError("cannot compile shaders/" + std::string(source.name) + ":\n" +
                    mapShaderLog(source, log.data()));
}

Program::Program(const Gl& gl, std::span<const ShaderSource* const> stages) : gl_(gl) {
  id_ = gl.CreateProgram();
  std::vector<GLuint> shaders;
  try {
    for (const ShaderSource* stage : stages) {
      shaders.push_back(compileShader(gl, *stage, stage->text));
      gl.AttachShader(id_, shaders.back());
    }
  } catch (...) {
    for (GLuint s : shaders) gl.DeleteShader(s);
    gl.DeleteProgram(id_);
    throw;
  }
  gl.LinkProgram(id_);
  for (GLuint s : shaders) gl.DeleteShader(s);
  GLint ok = 0;
  gl.GetProgramiv(id_, GL_LINK_STATUS, &ok);
  if (!ok) {
    std::vector<char> log(4096, '\0');
    gl.GetProgramInfoLog(id_, static_cast<GLsizei>(log.size()), nullptr, log.data());
    gl.DeleteProgram(id_);
    std::string names;
    for (const ShaderSource* stage : stages) names += "shaders/" + std::string(stage->name) + " ";
    throw ShaderError("cannot link " + names + ":\n" + log.data());
  }
}

Program::~Program() {
  gl_.DeleteProgram(id_);
}

GLint Program::location(const char* name) const {
  const GLint loc = gl_.GetUniformLocation(id_, name);
  if (loc < 0) throw ShaderError(std::string("program has no uniform ") + name);
  return loc;
}

void Program::set(const char* name, int value) const {
  gl_.ProgramUniform1i(id_, location(name), value);
}
void Program::set(const char* name, unsigned value) const {
  gl_.ProgramUniform1ui(id_, location(name), value);
}
void Program::set(const char* name, float value) const {
  gl_.ProgramUniform1f(id_, location(name), value);
}

void Program::set(const char* name, glm::vec2 value) const {
  gl_.ProgramUniform2f(id_, location(name), value.x, value.y);
}

void Program::set(const char* name, glm::vec3 value) const {
  gl_.ProgramUniform3f(id_, location(name), value.x, value.y, value.z);
}

void Program::set(const char* name, const glm::mat4& value) const {
  gl_.ProgramUniformMatrix4fv(id_, location(name), 1, GL_FALSE, &value[0][0]);
}

}  // namespace voxgi::gpu
