// GPU inject_lpv stage: shaders/lpv/inject_lpv.comp, one invocation per VPL, adding fixed-point
// lobes with atomics into a storage buffer that is read back as the sums.
#include <algorithm>
#include <vector>

#include "common/lpv/injection.h"
#include "common/lpv/sh_buffers.h"
#include "gpu/program.h"
#include "gpu/stages.h"
#include "gpu/volumes.h"

namespace voxgi::gpu {

void lpv::inject_lpv(GlContext& context, const StageContext& ctx, BufferSet& buffers) {
  const Gl& gl = beginStage(context, ctx, StageId::lpv_inject_lpv);
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
  Program program(gl, {&shaders::lpv_inject_lpv_comp});
  program.use();
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, vplBlock.get());
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, sumBlock.get());
  const auto groups = static_cast<GLuint>((injection.vpls.size() + 63) / 64);
  const GLuint width = std::min<GLuint>(std::max<GLuint>(groups, 1), 65535);
  if (groups > 0) gl.DispatchCompute(width, (groups + width - 1) / width, 1);
  gl.MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  gl.check("inject_lpv: dispatch");
  readWords(gl, sumBlock.get(), sums);
  gl.check("inject_lpv: reading back");
  buffers.put(std::move(sums));
}

}  // namespace voxgi::gpu
