// Backend selection shared by the voxgi subcommands.
#pragma once

#include <memory>
#include <string>

#include "common/pipeline.h"
#include "gpu/context.h"

namespace voxgi::tools {

struct BackendChoice {
  bool gpu = false;
  std::unique_ptr<gpu::GlContext> context;  // set when gpu
  std::string note;                         // why this backend, for the log line
  std::unique_ptr<StageBackend> runner;     // made by stages()
  // The stage backend of the choice (cpu::CpuBackend or gpu::GpuBackend on `context`).
  StageBackend& stages();
};

// "cpu", "gpu" (throws GlUnavailable if no context) or "auto" (a hardware GPU through EGL if there
// is one, else the CPU backend).
BackendChoice chooseBackend(const std::string& backend, gpu::GlPlatform platform);

}  // namespace voxgi::tools
