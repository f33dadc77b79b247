// GPU inject stage: shaders/lpv/inject.comp, one invocation per VPL (the emitters', then
// the RSM texels'), adding fixed-point lobes with atomics into a storage buffer that is read back
// as the sums.
#include <algorithm>
#include <vector>

#include "common/lpv/inject.h"
#include "common/lpv/rsm.h"
#include "common/lpv/sh_buffers.h"
#include "gpu/program.h"
#include "gpu/stages.h"
#include "gpu/volumes.h"

namespace voxgi::gpu {
void lpv::inject(GlContext& context, const StageContext& ctx, BufferSet& buffers) {
  const Gl& gl = beginStage(context, ctx, StageId::lpv_inject);
  const voxgi::lpv::ShBuffers sh = voxgi::lpv::shBuffers(ctx.settings.lpv);
  const voxgi::lpv::Injection injection = voxgi::lpv::prepareInjection(ctx);
  const int n = ctx.scene.grid.resolution;
  Buffer sums(sh.intensitySum, glm::ivec3(n));
  requireStorageBlock(gl, ctx, sums.words.size() * 4, "the injected SH sums");
  requireStorageBlock(gl, ctx,
                      sizeof(injection.params) + injection.vpls.size() * sizeof(shared::Vpl),
                      "the emitter VPLs");
  GlBuffer vplBlock(gl, createBlock(gl, injection.params, injection.vpls));
  GlBuffer sumBlock(gl, uploadWords(gl, sums));  // zeros
  Program program(gl, {&shaders::lpv_inject_comp});
  program.use();
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, vplBlock.get());
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, sumBlock.get());
  // Without an RSM its blocks are bound to the VPLs, which the emitters' pass never reads as such.
  for (GLuint b = 2; b <= 5; ++b) gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, b, vplBlock.get());
  program.set("uSource", 0);
  dispatchLinear(gl, injection.vpls.size());
  gl.check("inject: emitters");
  if (ctx.plan.runs(StageId::lpv_rsm)) {
    const voxgi::lpv::RsmSetup rsm = voxgi::lpv::prepareRsm(ctx.scene, ctx.settings);
    const Buffer& flux = buffers.at(BufferId::lpv_rsm_flux);
    requireStorageBlock(gl, ctx, flux.words.size() * 4, "the RSM flux");
    GlBuffer views(gl, createBlock(gl, rsm.params, rsm.views));
    GlBuffer fluxBlock(gl, uploadWords(gl, flux));
    GlBuffer normalBlock(gl, uploadWords(gl, buffers.at(BufferId::lpv_rsm_normal)));
    GlBuffer depthBlock(gl, uploadWords(gl, buffers.at(BufferId::lpv_rsm_depth)));
    gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, views.get());
    gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, fluxBlock.get());
    gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 4, normalBlock.get());
    gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 5, depthBlock.get());
    program.set("uSource", 1);
    dispatchLinear(gl, flux.elementCount());
    gl.check("inject: RSM texels");
  }
  readWords(gl, sumBlock.get(), sums);
  gl.check("inject: reading back");
  buffers.put(std::move(sums));
}

}  // namespace voxgi::gpu
