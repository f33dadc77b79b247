#include "tools/backend.h"

#include "cpu/backend.h"
#include "gpu/backend.h"

namespace voxgi::tools {

StageBackend& BackendChoice::stages() {
  if (!runner) {
    if (gpu)
      runner = std::make_unique<gpu::GpuBackend>(*context);
    else
      runner = std::make_unique<cpu::CpuBackend>();
  }
  return *runner;
}

BackendChoice chooseBackend(const std::string& backend, gpu::GlPlatform platform) {
  BackendChoice choice;
  if (backend == "cpu") return choice;
  if (backend == "gpu") {
    choice.context = gpu::GlContext::create(platform);
    choice.gpu = true;
    return choice;
  }
  try {
    auto context = gpu::GlContext::create(gpu::GlPlatform::egl);
    if (context->isHardware()) {
      choice.context = std::move(context);
      choice.gpu = true;
      return choice;
    }
    choice.note = "auto: no hardware GPU (" + context->renderer() + "), using the CPU backend";
  } catch (const gpu::GlUnavailable& e) {
    choice.note = std::string("auto: no GL context (") + e.what() + "), using the CPU backend";
  }
  return choice;
}

}  // namespace voxgi::tools
