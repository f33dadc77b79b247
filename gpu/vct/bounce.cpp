// GPU bounce stage: shaders/vct/bounce.comp per voxel, then the pyramid again with mip.comp
// (gpu/vct/pyramid.cpp), bounce.count times, all on the GPU; the last radiance and pyramid are read
// back.
#include "common/cone/cone_trace.h"
#include "common/mips.h"
#include "common/vct/radiance_buffers.h"
#include "gpu/program.h"
#include "gpu/vct/pyramid.h"
#include "gpu/stages.h"
#include "gpu/volumes.h"

namespace voxgi::gpu {

void vct::bounce(GlContext& context, const StageContext& ctx, BufferSet& buffers) {
  const Gl& gl = beginStage(context, ctx, StageId::vct_bounce);
  const int n = ctx.scene.grid.resolution;
  const MipMode mode = ctx.settings.vct.mip;
  const int faces = pyramidFaces(mode);
  const RadianceBuffers first = directRadiance(mode);
  const ConeTraceSetup setup = prepareGather(ctx);
  const bool levels = mipLevelCount(n) > 0;  // a 1^3 grid has no pyramid

  GlBuffer coneBlock(gl, createBlock(gl, setup.params, setup.cones));
  GlTexture direct(gl, uploadVolume(gl, buffers.at(first.radiance)));
  GlTexture albedo(gl, uploadVolume(gl, buffers.at(BufferId::common_voxelize_albedo)));
  GlTexture normal(gl, uploadVolume(gl, buffers.at(BufferId::common_voxelize_normal)));
  GlTexture radiance(gl, 0);  // the latest bounce; before the first, `direct` is read
  GlTexture pyramid(gl, levels ? uploadPyramid(gl, buffers.at(first.pyramid), n, faces)
                               : createVolume(gl, 4, glm::ivec3(1)));
  Program program(gl, {&shaders::vct_bounce_comp});
  program.set("uResolution", n);
  for (int b = 0; b < ctx.settings.vct.bounceCount; ++b) {
    GlTexture bounced(gl, createVolume(gl, 4, glm::ivec3(n)));
    program.use();
    const GLuint textures[] = {b == 0 ? direct.get() : radiance.get(), pyramid.get(), direct.get(),
                               albedo.get(), normal.get()};
    for (GLuint unit = 0; unit < 5; ++unit) gl.BindTextureUnit(unit, textures[unit]);
    gl.BindImageTexture(0, bounced.get(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, coneBlock.get());
    const auto groups = static_cast<GLuint>((n + 3) / 4);
    gl.DispatchCompute(groups, groups, groups);
    gl.MemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
                     GL_TEXTURE_UPDATE_BARRIER_BIT);
    gl.check("bounce: dispatch");
    radiance = std::move(bounced);
    if (levels) pyramid = buildPyramid(gl, radiance.get(), n, faces);
  }

  Buffer out(BufferId::vct_bounce_radiance, glm::ivec3(n));
  readVolume(gl, radiance.get(), 0, glm::ivec3(n), out);
  const BufferSpec& pyramidSpec = bufferSpec(pyramidBuffer(StageId::vct_bounce, mode));
  buffers.put(levels ? readPyramid(gl, pyramid.get(), pyramidSpec, n, faces)
                     : Buffer(pyramidSpec, shapeExtent(pyramidSpec.shape, n, {})));
  buffers.put(std::move(out));
  gl.check("bounce: reading back");
}

}  // namespace voxgi::gpu
