// CPU mip stage: the pyramid mip.mode asks for, built by cpu/pyramid.cpp.
#include "common/mips.h"
#include "cpu/pyramid.h"
#include "cpu/stages.h"

namespace voxgi::cpu {

void mip(const StageContext& ctx, BufferSet& buffers) {
  checkStageMemory(ctx, "mip");
  const char* name = pyramidName(ctx.plan.mip);
  buildPyramid(bufferSpec("mip", name), buffers.at("radiance"), ctx.scene.grid.resolution,
               buffers[name]);
}

}  // namespace voxgi::cpu
