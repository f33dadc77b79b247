// GPU shade_lpv stage: shaders/lpv/shade_lpv.comp per pixel on the accumulated volume and the
// gbuffer's surfaces, packed per pixel on the host.
#include <vector>

#include "common/lpv/propagation.h"
#include "common/lpv/sh_buffers.h"
#include "gpu/program.h"
#include "gpu/stages.h"
#include "gpu/volumes.h"

namespace voxgi::gpu {

void lpv::shade_lpv(GlContext& context, const StageContext& ctx, BufferSet& buffers) {
  const Gl& gl = beginStage(context, ctx, StageId::lpv_shade_lpv);
  using enum BufferId;
  const voxgi::lpv::ShBuffers sh = voxgi::lpv::shBuffers(ctx.settings.lpv);
  const shared::ShadeParams params = voxgi::lpv::shadeParams(ctx);
  const Buffer& accumulated = buffers.at(sh.accumulated);
  const Buffer& objectId = buffers.at(common_gbuffer_object_id);
  const size_t pixels = objectId.elementCount();
  const Buffer* fields[] = {
      &buffers.at(common_gbuffer_pixel_position), &buffers.at(common_gbuffer_pixel_normal),
      &buffers.at(common_gbuffer_pixel_albedo), buffers.find(common_gbuffer_pixel_emission)};
  std::vector<float> surfaces(pixels * 12, 0.0f);
  for (int f = 0; f < 4; ++f)
    if (fields[f] != nullptr)
      for (size_t e = 0; e < pixels; ++e)
        for (int c = 0; c < 3; ++c)
          surfaces[12 * e + size_t(3 * f + c)] = fields[f]->get<float>(e, c);

  requireStorageBlock(gl, ctx, accumulated.words.size() * 4, "the accumulated SH volume");
  GlBuffer paramBlock(gl, createBuffer(gl, sizeof params, &params));
  GlBuffer volume(gl, uploadWords(gl, accumulated));
  GlBuffer ids(gl, uploadWords(gl, objectId));
  GlBuffer surfaceBlock(gl, createBuffer(gl, surfaces.size() * 4, surfaces.data()));
  GlBuffer indirect(gl, createBuffer(gl, pixels * 12, nullptr));
  GlBuffer color(gl, createBuffer(gl, pixels * 12, nullptr));
  Program program(gl, {&shaders::lpv_shade_lpv_comp});
  program.set("uPixels", int(pixels));
  program.set("uBackground", ctx.scene.background);
  program.use();
  const GLuint blocks[] = {paramBlock.get(),   volume.get(),   ids.get(),
                           surfaceBlock.get(), indirect.get(), color.get()};
  for (GLuint b = 0; b < 6; ++b) gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, b, blocks[b]);
  gl.DispatchCompute(GLuint((pixels + 63) / 64), 1, 1);
  gl.MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  gl.check("shade_lpv: dispatch");
  Buffer indirectOut(lpv_shade_lpv_indirect_diffuse, objectId.extent);
  Buffer colorOut(lpv_shade_lpv_color, objectId.extent);
  readWords(gl, indirect.get(), indirectOut);
  readWords(gl, color.get(), colorOut);
  gl.check("shade_lpv: reading back");
  buffers.put(std::move(indirectOut));
  buffers.put(std::move(colorOut));
}

}  // namespace voxgi::gpu
