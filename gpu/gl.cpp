#include "gpu/gl.h"

#include <algorithm>
#include <cstdio>

namespace voxgi::gpu {

void Gl::load(ProcLoader getProcAddress) {
#define VOXGI_GL(type, name)                                 \
  name = reinterpret_cast<type>(getProcAddress("gl" #name)); \
  if (name == nullptr) throw GlUnavailable("GL context lacks gl" #name);
#include "gpu/gl_functions.inc"
}

void Gl::check(const char* what) const {
  const GLenum error = GetError();
  if (error != GL_NO_ERROR) {
    char code[16];
    std::snprintf(code, sizeof code, "0x%04x", error);
    throw std::runtime_error(std::string(what) + ": GL error " + code);
  }
}

GLuint createBuffer(const Gl& gl, size_t bytes, const void* data) {
  GLuint id = 0;
  gl.CreateBuffers(1, &id);
  gl.NamedBufferStorage(id, static_cast<GLsizeiptr>(std::max<size_t>(bytes, 1)),
                        bytes > 0 ? data : nullptr, 0);
  return id;
}

void dispatchLinear(const Gl& gl, uint64_t count) {
  if (count == 0) return;
  const auto groups = static_cast<GLuint>((count + 63) / 64);
  const GLuint width = std::min<GLuint>(groups, 65535);
  gl.DispatchCompute(width, (groups + width - 1) / width, 1);
  gl.MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
}

void deleteBuffer(const Gl& gl, GLuint id) {
  gl.DeleteBuffers(1, &id);
}
void deleteTexture(const Gl& gl, GLuint id) {
  gl.DeleteTextures(1, &id);
}

}  // namespace voxgi::gpu
