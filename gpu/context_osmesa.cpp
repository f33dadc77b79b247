// OSMesa context, loaded with dlopen so that voxgi still builds and runs (EGL only) on systems
// whose Mesa (>= 25.1) no longer ships libOSMesa.
#include <dlfcn.h>

#include <vector>

// glcorearb.h first: GL/osmesa.h pulls in GL/gl.h, which would hide glcorearb's 1.0/1.1 typedefs.
#include "gpu/context.h"
#include <GL/osmesa.h>

namespace voxgi::gpu {
namespace {

class OsmesaContext : public GlContext {
 public:
  OsmesaContext() : GlContext(GlPlatform::osmesa) {
    for (const char* name : {"libOSMesa.so.8", "libOSMesa.so.6", "libOSMesa.so"})
      if ((library_ = dlopen(name, RTLD_NOW | RTLD_LOCAL)) != nullptr) break;
    if (library_ == nullptr) throw GlUnavailable("OSMesa: libOSMesa not found");
    auto create = symbol<decltype(&OSMesaCreateContextAttribs)>("OSMesaCreateContextAttribs");
    auto getProc = symbol<decltype(&OSMesaGetProcAddress)>("OSMesaGetProcAddress");
    destroy_ = symbol<decltype(&OSMesaDestroyContext)>("OSMesaDestroyContext");
    const int attribs[] = {OSMESA_FORMAT,
                           OSMESA_RGBA,
                           OSMESA_DEPTH_BITS,
                           0,
                           OSMESA_PROFILE,
                           OSMESA_CORE_PROFILE,
                           OSMESA_CONTEXT_MAJOR_VERSION,
                           4,
                           OSMESA_CONTEXT_MINOR_VERSION,
                           5,
                           0};
    context_ = create(attribs, nullptr);
    if (context_ == nullptr) throw GlUnavailable("OSMesa: cannot create a 4.5 core context");
    makeCurrent_ = symbol<decltype(&OSMesaMakeCurrent)>("OSMesaMakeCurrent");
    OsmesaContext::makeCurrent();
    loadFunctions(reinterpret_cast<Gl::ProcLoader>(getProc));
  }
  void makeCurrent() override {
    // OSMesa needs a colour buffer to make a context current; voxgi renders into FBOs.
    if (!makeCurrent_(context_, pixels_.data(), GL_UNSIGNED_BYTE, 1, 1))
      throw GlUnavailable("OSMesa: cannot make the context current");
  }
  ~OsmesaContext() override {
    if (context_ != nullptr) destroy_(context_);
    // libOSMesa stays loaded: unloading Mesa while its threads wind down is not safe.
  }

 private:
  template <class F>
  F symbol(const char* name) {
    auto f = reinterpret_cast<F>(dlsym(library_, name));
    if (f == nullptr) throw GlUnavailable(std::string("OSMesa: missing ") + name);
    return f;
  }
  void* library_ = nullptr;
  OSMesaContext context_ = nullptr;
  decltype(&OSMesaDestroyContext) destroy_ = nullptr;
  decltype(&OSMesaMakeCurrent) makeCurrent_ = nullptr;
  std::vector<unsigned char> pixels_ = std::vector<unsigned char>(4);
};

}  // namespace

std::unique_ptr<GlContext> createOsmesaContext() {
  return std::make_unique<OsmesaContext>();
}

}  // namespace voxgi::gpu
