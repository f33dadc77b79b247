#include "gpu/context.h"

#include "common/error.h"

namespace voxgi::gpu {

GlPlatform parseGlPlatform(const std::string& text) {
  if (text == "osmesa") return GlPlatform::osmesa;
  if (text == "egl") return GlPlatform::egl;
  throw InputError("--gl", "", "must be osmesa or egl, got '" + text + "'");
}

const char* glPlatformName(GlPlatform platform) {
  return platform == GlPlatform::egl ? "egl" : "osmesa";
}

std::unique_ptr<GlContext> GlContext::create(GlPlatform platform) {
  return platform == GlPlatform::egl ? createEglContext() : createOsmesaContext();
}

void GlContext::loadFunctions(Gl::ProcLoader loader) {
  gl_.load(loader);
  GLint major = 0, minor = 0;
  gl_.GetIntegerv(GL_MAJOR_VERSION, &major);
  gl_.GetIntegerv(GL_MINOR_VERSION, &minor);
  if (major * 10 + minor < 45)
    throw GlUnavailable("OpenGL 4.5 core needed, context is " + std::to_string(major) + "." +
                        std::to_string(minor));
}

std::string GlContext::renderer() const {
  const auto* r = reinterpret_cast<const char*>(gl_.GetString(GL_RENDERER));
  return r != nullptr ? r : "";
}

bool GlContext::isHardware() const {
  const std::string r = renderer();
  for (const char* soft : {"llvmpipe", "softpipe", "swrast", "Software"})
    if (r.find(soft) != std::string::npos) return false;
  return true;
}

GLint GlContext::max3dTextureSize() const {
  GLint size = 0;
  gl_.GetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &size);
  return size;
}

}  // namespace voxgi::gpu
