// The OpenGL backend: one function per stage of common/stages.inc, gpu::<owner>::<stage>, the twin
// of cpu/stages.h. Runs on the current context of `context` (gpu/context.h). gpu/backend.cpp takes
// the address of each, so a stage without its GPU function does not link.
#pragma once

#include "common/stage.h"
#include "gpu/context.h"

namespace voxgi::gpu {

#define VOXGI_TECHNIQUE(technique, image_stage, image, summary)
#define VOXGI_EFFECT(owner, effect, meaning)
#define VOXGI_STAGE(owner, stage, reads, summary)                              \
  namespace owner {                                                            \
  void stage(GlContext& context, const StageContext& ctx, BufferSet& buffers); \
  }
#define VOXGI_STEP(technique, owner, stage)
#define VOXGI_BUFFER(owner, stage, buffer, type, components, shape, need, meaning)
#include "common/stages.inc"

}  // namespace voxgi::gpu
