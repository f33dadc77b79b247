// EGL context: a hardware device through EGL_EXT_platform_device if there is one, otherwise Mesa's
// surfaceless platform (llvmpipe). No surface: voxgi renders into framebuffer objects.
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <dlfcn.h>
#include <link.h>

#include <cstring>
#include <string>
#include <vector>

#include "gpu/context.h"

namespace voxgi::gpu {
namespace {

#ifndef EGL_PLATFORM_SURFACELESS_MESA
#define EGL_PLATFORM_SURFACELESS_MESA 0x31DD
#endif

// Keeps the DRI drivers EGL loaded (Mesa's llvmpipe, and LLVM with it) mapped until the process
// ends, as libOSMesa stays (gpu/context_osmesa.cpp): eglTerminate would unload the driver while
// its threads may still wind down, and code that is gone cannot be named in a crash or a leak
// report (LeakSanitizer, tests/sanitizers/lsan.supp).
void keepDriversLoaded() {
  std::vector<std::string> drivers;
  dl_iterate_phdr(
      [](dl_phdr_info* info, size_t, void* out) {
        if (info->dlpi_name != nullptr && std::strstr(info->dlpi_name, "/dri/") != nullptr)
          static_cast<std::vector<std::string>*>(out)->emplace_back(info->dlpi_name);
        return 0;
      },
      &drivers);
  for (const std::string& d : drivers) dlopen(d.c_str(), RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE);
}

class EglContext : public GlContext {
 public:
  EglContext() : GlContext(GlPlatform::egl) {}
  ~EglContext() override {
    if (display_ != EGL_NO_DISPLAY) {
      eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
      if (context_ != EGL_NO_CONTEXT) eglDestroyContext(display_, context_);
      eglTerminate(display_);
    }
  }

  // Tries one display; on success the context is current. Returns false and cleans up otherwise.
  bool open(EGLDisplay display) {
    EGLint major = 0, minor = 0;
    if (display == EGL_NO_DISPLAY || !eglInitialize(display, &major, &minor)) return false;
    keepDriversLoaded();
    display_ = display;
    const EGLint configAttribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint count = 0;
    eglChooseConfig(display, configAttribs, &config, 1,
                    &count);  // may find none: no-config is fine
    const EGLint contextAttribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                                     4,
                                     EGL_CONTEXT_MINOR_VERSION,
                                     5,
                                     EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                     EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                     EGL_NONE};
    if (eglBindAPI(EGL_OPENGL_API))
      context_ = eglCreateContext(display, count > 0 ? config : EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT,
                                  contextAttribs);
    if (context_ != EGL_NO_CONTEXT &&
        eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
      return true;
    if (context_ != EGL_NO_CONTEXT) eglDestroyContext(display, context_);
    context_ = EGL_NO_CONTEXT;
    eglTerminate(display);
    display_ = EGL_NO_DISPLAY;
    return false;
  }

  void makeCurrent() override {
    if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
      throw GlUnavailable("EGL: cannot make the context current");
  }

  void finish() { loadFunctions(reinterpret_cast<Gl::ProcLoader>(&eglGetProcAddress)); }

 private:
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
};

}  // namespace

std::unique_ptr<GlContext> createEglContext() {
  auto getPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
      eglGetProcAddress("eglGetPlatformDisplayEXT"));
  auto queryDevices =
      reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
  if (getPlatformDisplay == nullptr) throw GlUnavailable("EGL: no eglGetPlatformDisplayEXT");

  // Hardware devices first.
  if (queryDevices != nullptr) {
    EGLint count = 0;
    queryDevices(0, nullptr, &count);
    std::vector<EGLDeviceEXT> devices(static_cast<size_t>(count));
    if (count > 0 && queryDevices(count, devices.data(), &count)) {
      for (EGLDeviceEXT device : devices) {
        auto context = std::make_unique<EglContext>();
        if (!context->open(getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, device, nullptr))) continue;
        context->finish();
        if (context->isHardware()) return context;
      }
    }
  }
  auto context = std::make_unique<EglContext>();
  if (!context->open(
          getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr)))
    throw GlUnavailable("EGL: no hardware device and no surfaceless platform with OpenGL 4.5 core");
  context->finish();
  return context;
}

}  // namespace voxgi::gpu
