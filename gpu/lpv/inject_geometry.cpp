// GPU inject_geometry stage: shaders/lpv/inject_geometry.comp per geometry-volume cell on
// voxelize's sums uploaded as storage buffers.
#include "gpu/program.h"
#include "gpu/stages.h"
#include "gpu/volumes.h"

namespace voxgi::gpu {

void lpv::inject_geometry(GlContext& context, const StageContext& ctx, BufferSet& buffers) {
  const Gl& gl = beginStage(context, ctx, StageId::lpv_inject_geometry);
  const int n = ctx.scene.grid.resolution;
  const Buffer& normals = buffers.at(BufferId::common_voxelize_normal_sum);
  requireStorageBlock(gl, ctx, normals.words.size() * 4, "voxelize's normal sums");
  GlBuffer weightBlock(gl, uploadWords(gl, buffers.at(BufferId::common_voxelize_weight_sum)));
  GlBuffer normalBlock(gl, uploadWords(gl, normals));
  Buffer blocking(BufferId::lpv_inject_geometry_blocking, glm::ivec3(n));
  GlBuffer blockingBlock(gl, createBuffer(gl, blocking.words.size() * 4, nullptr));
  Program program(gl, {&shaders::lpv_inject_geometry_comp});
  program.set("uResolution", n);
  program.use();
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, weightBlock.get());
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, normalBlock.get());
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, blockingBlock.get());
  const auto groups = static_cast<GLuint>((n + 3) / 4);
  gl.DispatchCompute(groups, groups, groups);
  gl.MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  gl.check("inject_geometry: dispatch");
  readWords(gl, blockingBlock.get(), blocking);
  gl.check("inject_geometry: reading back");
  buffers.put(std::move(blocking));
}

}  // namespace voxgi::gpu
