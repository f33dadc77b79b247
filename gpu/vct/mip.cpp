// GPU mip stage: shaders/vct/mip.comp builds the pyramid texture level by level from the uploaded
// radiance volume (gpu/vct/pyramid.cpp); the pyramid is read back for the next stage and for
// `voxgi diff`.
#include "common/mips.h"
#include "common/vct/radiance_buffers.h"
#include "gpu/vct/pyramid.h"
#include "gpu/stages.h"
#include "gpu/volumes.h"

namespace voxgi::gpu {

void vct::mip(GlContext& context, const StageContext& ctx, BufferSet& buffers) {
  const Gl& gl = beginStage(context, ctx, StageId::vct_mip);
  const int n = ctx.scene.grid.resolution;
  const int faces = pyramidFaces(ctx.settings.vct.mip);
  const BufferSpec& spec = bufferSpec(pyramidBuffer(StageId::vct_mip, ctx.settings.vct.mip));
  if (mipLevelCount(n) == 0) {  // a 1^3 grid has no levels above the base
    buffers.put(Buffer(spec, shapeExtent(spec.shape, n, {})));
    return;
  }
  GlTexture radiance(gl, uploadVolume(gl, buffers.at(BufferId::vct_light_voxels_radiance)));
  const GlTexture pyramid = buildPyramid(gl, radiance.get(), n, faces);
  buffers.put(readPyramid(gl, pyramid.get(), spec, n, faces));
  gl.check("mip: reading back");
}

}  // namespace voxgi::gpu
