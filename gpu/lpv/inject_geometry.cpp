// GPU inject_geometry stage: shaders/lpv/inject_geometry.comp per geometry-volume cell on
// voxelize's sums uploaded as storage buffers; with inject_geometry.blockers=rsm, per light
// shaders/lpv/inject_geometry_rsm.comp scatters its texels' surfaces into a scratch volume that
// inject_geometry.comp then merges, and finally turns into the blocking potential.
#include <algorithm>

#include "common/lpv/rsm.h"
#include "gpu/program.h"
#include "gpu/stages.h"
#include "gpu/volumes.h"

namespace voxgi::gpu {
namespace {

// The per-cell pass of inject_geometry.comp in `mode` over an N^3 grid.
void cellPass(const Gl& gl, const Program& program, int n, int mode) {
  program.set("uMode", mode);
  const auto groups = static_cast<GLuint>((n + 3) / 4);
  gl.DispatchCompute(groups, groups, groups);
  gl.MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
}

}  // namespace

void lpv::inject_geometry(GlContext& context, const StageContext& ctx, BufferSet& buffers) {
  const Gl& gl = beginStage(context, ctx, StageId::lpv_inject_geometry);
  const int n = ctx.scene.grid.resolution;
  const bool fromRsm = ctx.plan.on(Effect::rsm_blockers);
  const Buffer& normals = buffers.at(BufferId::common_voxelize_normal_sum);
  requireStorageBlock(gl, ctx, normals.words.size() * 4, "voxelize's normal sums");
  GlBuffer weightBlock(gl, uploadWords(gl, buffers.at(BufferId::common_voxelize_weight_sum)));
  GlBuffer normalBlock(gl, uploadWords(gl, normals));
  Buffer blocking(BufferId::lpv_inject_geometry_blocking, glm::ivec3(n));
  Buffer sums(BufferId::lpv_inject_geometry_blocker_sum, glm::ivec3(fromRsm ? n : 1));
  GlBuffer blockingBlock(gl, createBuffer(gl, blocking.words.size() * 4, nullptr));
  GlBuffer scratchBlock(gl, uploadWords(gl, sums));  // zeros
  GlBuffer sumBlock(gl, uploadWords(gl, sums));
  Program cells(gl, {&shaders::lpv_inject_geometry_comp});
  cells.set("uResolution", n);
  const GLuint blocks[] = {weightBlock.get(), normalBlock.get(), blockingBlock.get(),
                           scratchBlock.get(), sumBlock.get()};
  const auto bindCells = [&] {
    cells.use();
    for (GLuint b = 0; b < 5; ++b) gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, b, blocks[b]);
  };
  if (!fromRsm) {
    bindCells();
    cellPass(gl, cells, n, 0);
  } else if (ctx.plan.runs(StageId::lpv_rsm)) {
    const voxgi::lpv::RsmSetup rsm = voxgi::lpv::prepareRsm(ctx.scene, ctx.settings);
    const Buffer& depth = buffers.at(BufferId::lpv_rsm_depth);
    GlBuffer views(gl, createBlock(gl, rsm.params, rsm.views));
    GlBuffer depthBlock(gl, uploadWords(gl, depth));
    GlBuffer rsmNormalBlock(gl, uploadWords(gl, buffers.at(BufferId::lpv_rsm_normal)));
    Program scatter(gl, {&shaders::lpv_inject_geometry_rsm_comp});
    scatter.set("uResolution", n);
    const int r = rsm.params.resolution;
    for (size_t first = 0; first < rsm.views.size(); first += size_t(rsm.views[first].viewCount)) {
      const int count = rsm.views[first].viewCount;
      gl.ClearNamedBufferData(scratchBlock.get(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT,
                              nullptr);
      scatter.use();
      scatter.set("uFirstView", int(first));
      scatter.set("uViewCount", count);
      const GLuint scatterBlocks[] = {views.get(), depthBlock.get(), rsmNormalBlock.get(),
                                      scratchBlock.get()};
      for (GLuint b = 0; b < 4; ++b)
        gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, b, scatterBlocks[b]);
      dispatchLinear(gl, uint64_t(r) * uint64_t(r) * uint64_t(count));
      bindCells();
      cellPass(gl, cells, n, 1);
    }
  }
  if (fromRsm) {
    bindCells();
    cellPass(gl, cells, n, 2);
    readWords(gl, sumBlock.get(), sums);
  }
  gl.check("inject_geometry: dispatch");
  readWords(gl, blockingBlock.get(), blocking);
  gl.check("inject_geometry: reading back");
  if (fromRsm) buffers.put(std::move(sums));
  buffers.put(std::move(blocking));
}

}  // namespace voxgi::gpu
