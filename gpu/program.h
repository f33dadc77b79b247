// GLSL programs built from the embedded shaders (shaders/). Compile and link errors become
// ShaderError with locations rewritten to shaders/<file>:<line>.
#pragma once

#include <initializer_list>
#include <string>
#include <string_view>

#include <glm/glm.hpp>

#include "gpu/gl.h"

namespace voxgi::gpu {

class ShaderError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class Program {
 public:
  // `stages`: embedded file names; the stage type comes from the extension (.vert .geom .frag
  // .comp).
  Program(const Gl& gl, std::initializer_list<std::string_view> stages);
  Program(const Program&) = delete;
  Program& operator=(const Program&) = delete;
  ~Program();

  GLuint id() const { return id_; }
  void use() const { gl_.UseProgram(id_); }
  void set(const char* name, int value) const;
  void set(const char* name, unsigned value) const;
  void set(const char* name, float value) const;
  void set(const char* name, glm::vec2 value) const;
  void set(const char* name, glm::vec3 value) const;
  void set(const char* name, const glm::mat4& value) const;

 private:
  GLint location(const char* name) const;
  const Gl& gl_;
  GLuint id_ = 0;
};

// Compiles GLSL text (as embedded, or any other for tests) and returns the shader, or throws
// ShaderError with the mapped log.
GLuint compileShader(const Gl& gl, std::string_view fileName, std::string_view text);

}  // namespace voxgi::gpu
