// The OpenGL backend: one function per stage of common/stages.inc, the twin of cpu/stages.h.
// Runs on the current context of `context` (gpu/context.h).
#pragma once

#include "common/stage.h"
#include "gpu/context.h"

namespace voxgi::gpu {

#define VOXGI_STAGE(stage, summary) \
  void stage(GlContext& context, const StageContext& ctx, BufferSet& buffers);
#include "common/stages.inc"
#undef VOXGI_STAGE

}  // namespace voxgi::gpu
