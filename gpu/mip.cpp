// GPU mip stage: shaders/mip.comp builds the pyramid texture level by level from the uploaded
// radiance volume (gpu/pyramid.cpp); the pyramid is read back for the next stage and for
// `voxgi diff`.
#include "common/mips.h"
#include "gpu/pyramid.h"
#include "gpu/stages.h"
#include "gpu/volumes.h"

namespace voxgi::gpu {

void mip(GlContext& context, const StageContext& ctx, BufferSet& buffers) {
  const Gl& gl = beginStage(context, ctx, "mip");
  const int n = ctx.scene.grid.resolution;
  const int faces = pyramidFaces(ctx.plan.mip);
  const BufferSpec& spec = bufferSpec("mip", pyramidName(ctx.plan.mip));
  if (mipLevelCount(n) == 0) {  // a 1^3 grid has no levels above the base
    buffers[std::string(spec.name)] = Buffer(spec, shapeExtent(spec.shape, n, {}));
    return;
  }
  GlTexture radiance(gl, uploadVolume(gl, buffers.at("radiance")));
  const GlTexture pyramid = buildPyramid(gl, radiance.get(), n, faces);
  buffers[std::string(spec.name)] = readPyramid(gl, pyramid.get(), spec, n, faces);
  gl.check("mip: reading back");
}

}  // namespace voxgi::gpu
