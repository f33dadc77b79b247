// CPU mip stage: the pyramid mip.mode asks for, built by cpu/vct/pyramid.cpp.
#include "common/vct/radiance_buffers.h"
#include "cpu/stages.h"
#include "cpu/vct/pyramid.h"

namespace voxgi::cpu {

void vct::mip(const StageContext& ctx, BufferSet& buffers) {
  checkStageMemory(ctx, StageId::vct_mip);
  const BufferId id = pyramidBuffer(StageId::vct_mip, ctx.settings.vct.mip);
  // In a sequence the frame before's pyramid is rebuilt in place, every word rewritten: its pages
  // stay mapped instead of being faulted in again each frame.
  Buffer pyramid = ctx.previous != nullptr ? ctx.previous->stash.take(id) : Buffer{};
  buildPyramid(bufferSpec(id), buffers.at(BufferId::vct_light_voxels_radiance),
               ctx.scene.grid.resolution, pyramid);
  buffers.put(std::move(pyramid));
}

}  // namespace voxgi::cpu
