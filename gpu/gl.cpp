#include "gpu/gl.h"

#include <cstdio>

namespace voxgi::gpu {

void Gl::load(ProcLoader getProcAddress) {
#define VOXGI_GL(type, name)                                 \
  name = reinterpret_cast<type>(getProcAddress("gl" #name)); \
  if (name == nullptr) throw GlUnavailable("GL context lacks gl" #name);
#include "gpu/gl_functions.inc"
#undef VOXGI_GL
}

void Gl::check(const char* what) const {
  const GLenum error = GetError();
  if (error != GL_NO_ERROR) {
    char code[16];
    std::snprintf(code, sizeof code, "0x%04x", error);
    throw std::runtime_error(std::string(what) + ": GL error " + code);
  }
}

void deleteBuffer(const Gl& gl, GLuint id) {
  gl.DeleteBuffers(1, &id);
}
void deleteTexture(const Gl& gl, GLuint id) {
  gl.DeleteTextures(1, &id);
}

}  // namespace voxgi::gpu
