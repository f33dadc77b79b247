// The CPU reference backend: one function per stage of common/stages.inc. Deterministic for any
// thread count (TBB; scatters accumulate in integers).
#pragma once

#include "common/stage.h"

namespace voxgi::cpu {

#define VOXGI_STAGE(stage, summary) void stage(const StageContext& ctx, BufferSet& buffers);
#include "common/stages.inc"
#undef VOXGI_STAGE

}  // namespace voxgi::cpu
