// GLSL programs built from the embedded shaders (shaders/). Compile and link errors become
// ShaderError with locations rewritten to shaders/<file>:<line>.
#pragma once

#include <initializer_list>
#include <span>
#include <string>
#include <string_view>

#include <glm/glm.hpp>

#include "gpu/gl.h"
#include "shaders/embedded.h"

namespace voxgi::gpu {

class ShaderError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class Program {
 public:
  // `stages`: embedded shaders (shaders/embedded.h); the stage type comes from the file's
  // extension (.vert .geom .frag .comp).
  Program(const Gl& gl, std::span<const ShaderSource* const> stages);
  Program(const Gl& gl, std::initializer_list<const ShaderSource*> stages)
      : Program(gl, std::span<const ShaderSource* const>(stages.begin(), stages.size())) {}
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

// Compiles `text` as the stage of `source` (its own text, or an edited copy in tests) and returns
// the shader, or throws ShaderError with the log's locations mapped through source's file table.
GLuint compileShader(const Gl& gl, const ShaderSource& source, std::string_view text);

}  // namespace voxgi::gpu
