// The CPU reference backend: one function per stage of common/stages.inc, cpu::<owner>::<stage>
// (cpu/vct/light_voxels.cpp defines cpu::vct::light_voxels). Deterministic for any thread count
// (TBB; scatters accumulate in integers). cpu/backend.cpp takes the address of each, so a stage
// without its CPU function does not link.
#pragma once

#include "common/stage.h"

namespace voxgi::cpu {

#define VOXGI_TECHNIQUE(technique, image_stage, image, summary)
#define VOXGI_EFFECT(owner, effect, meaning)
#define VOXGI_STAGE(owner, stage, reads, summary)          \
  namespace owner {                                        \
  void stage(const StageContext& ctx, BufferSet& buffers); \
  }
#define VOXGI_STEP(technique, owner, stage)
#define VOXGI_BUFFER(owner, stage, buffer, type, components, shape, need, meaning)
#include "common/stages.inc"

}  // namespace voxgi::cpu
