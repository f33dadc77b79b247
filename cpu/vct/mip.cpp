// CPU mip stage: the pyramid mip.mode asks for, built by cpu/vct/pyramid.cpp.
#include "common/vct/radiance_buffers.h"
#include "cpu/stages.h"
#include "cpu/vct/pyramid.h"

namespace voxgi::cpu {

void vct::mip(const StageContext& ctx, BufferSet& buffers) {
  checkStageMemory(ctx, StageId::vct_mip);
  const BufferId id = pyramidBuffer(StageId::vct_mip, ctx.settings.vct.mip);
  // Rebuilt in place when the set already holds it (a pyramid rebuilt every frame keeps its pages).
  Buffer pyramid = buffers.take(id);
  buildPyramid(bufferSpec(id), buffers.at(BufferId::vct_light_voxels_radiance),
               ctx.scene.grid.resolution, pyramid);
  buffers.put(std::move(pyramid));
}

}  // namespace voxgi::cpu
