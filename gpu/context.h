// Headless OpenGL 4.5 core contexts behind one interface: OSMesa (llvmpipe; removed in Mesa 25.1)
// and EGL (the device platform for real GPUs, EGL_MESA_platform_surfaceless for llvmpipe).
#pragma once

#include <memory>
#include <string>

#include "gpu/gl.h"

namespace voxgi::gpu {

enum class GlPlatform { osmesa, egl };
GlPlatform parseGlPlatform(const std::string& text);  // "osmesa" | "egl"; throws InputError
const char* glPlatformName(GlPlatform platform);      // its --gl name

class GlContext {
 public:
  // Creates a context and makes it current on this thread. Throws GlUnavailable.
  static std::unique_ptr<GlContext> create(GlPlatform platform);
  virtual ~GlContext() = default;

  const Gl& gl() const { return gl_; }
  // Makes this context current on the calling thread (GPU stages call it on entry).
  virtual void makeCurrent() = 0;
  std::string renderer() const;
  // True unless the renderer is a software rasterizer (llvmpipe, softpipe, swrast).
  bool isHardware() const;
  GlPlatform platform() const { return platform_; }
  GLint max3dTextureSize() const;

 protected:
  explicit GlContext(GlPlatform p) : platform_(p) {}
  void loadFunctions(Gl::ProcLoader loader);  // also checks for a 4.5 context
  Gl gl_;

 private:
  GlPlatform platform_;
};

std::unique_ptr<GlContext> createEglContext();
std::unique_ptr<GlContext> createOsmesaContext();

}  // namespace voxgi::gpu
