// GPU shade stage: shaders/lpv/shade.comp per pixel on the accumulated volume, the
// gbuffer's surfaces (packed per pixel on the host) and, with lights, the RSM depth.
#include <vector>

#include "common/lpv/propagate.h"
#include "common/lpv/rsm.h"
#include "common/lpv/sh_buffers.h"
#include "gpu/program.h"
#include "gpu/stages.h"
#include "gpu/volumes.h"

namespace voxgi::gpu {

void lpv::shade(GlContext& context, const StageContext& ctx, BufferSet& buffers) {
  const Gl& gl = beginStage(context, ctx, StageId::lpv_shade);
  using enum BufferId;
  const voxgi::lpv::ShBuffers sh = voxgi::lpv::shBuffers(ctx.settings.lpv);
  const shared::ShadeParams params = voxgi::lpv::shadeParams(ctx);
  const Buffer& accumulated = buffers.at(sh.accumulated);
  const Buffer& objectId = buffers.at(common_gbuffer_object_id);
  const size_t pixels = objectId.elementCount();
  // Per pixel: position, normal, albedo, emission (3 floats each), specular (4).
  const Buffer* fields[] = {
      &buffers.at(common_gbuffer_pixel_position), &buffers.at(common_gbuffer_pixel_normal),
      &buffers.at(common_gbuffer_pixel_albedo), buffers.find(common_gbuffer_pixel_emission),
      &buffers.at(common_gbuffer_pixel_specular)};
  std::vector<float> surfaces(pixels * 16, 0.0f);
  for (int f = 0; f < 5; ++f)
    if (fields[f] != nullptr)
      for (size_t e = 0; e < pixels; ++e)
        for (int c = 0; c < fields[f]->components(); ++c)
          surfaces[16 * e + size_t(3 * f + c)] = fields[f]->get<float>(e, c);

  // Lights, views and depth: a record each when the rsm stage did not run (never read then).
  voxgi::lpv::RsmSetup rsm = voxgi::lpv::prepareRsm(ctx.scene, ctx.settings);
  std::vector<shared::LightData> lights = rsm.lights;
  lights.resize(std::max<size_t>(lights.size(), 1));
  rsm.views.resize(std::max<size_t>(rsm.views.size(), 1));
  const Buffer* depth = buffers.find(lpv_rsm_depth);
  requireStorageBlock(gl, ctx, accumulated.words.size() * 4, "the accumulated SH volume");
  GlBuffer paramBlock(gl, createBuffer(gl, sizeof params, &params));
  GlBuffer volume(gl, uploadWords(gl, accumulated));
  GlBuffer ids(gl, uploadWords(gl, objectId));
  GlBuffer surfaceBlock(gl, createBuffer(gl, surfaces.size() * 4, surfaces.data()));
  GlBuffer indirect(gl, createBuffer(gl, pixels * 12, nullptr));
  GlBuffer color(gl, createBuffer(gl, pixels * 12, nullptr));
  GlBuffer lightBlock(gl,
                      createBuffer(gl, lights.size() * sizeof(shared::LightData), lights.data()));
  GlBuffer viewBlock(gl, createBlock(gl, rsm.params, rsm.views));
  const float none = 0.0f;
  GlBuffer depthBlock(gl, depth != nullptr ? uploadWords(gl, *depth) : createBuffer(gl, 4, &none));
  GlBuffer directDiffuse(gl, createBuffer(gl, pixels * 12, nullptr));
  GlBuffer directSpecular(gl, createBuffer(gl, pixels * 12, nullptr));
  Program program(gl, {&shaders::lpv_shade_comp});
  program.set("uPixels", int(pixels));
  program.set("uBackground", ctx.scene.background);
  program.use();
  const GLuint blocks[] = {paramBlock.get(),    volume.get(),        ids.get(),
                           surfaceBlock.get(),  indirect.get(),      color.get(),
                           lightBlock.get(),    viewBlock.get(),     depthBlock.get(),
                           directDiffuse.get(), directSpecular.get()};
  for (GLuint b = 0; b < 11; ++b) gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, b, blocks[b]);
  gl.DispatchCompute(GLuint((pixels + 63) / 64), 1, 1);
  gl.MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  gl.check("shade: dispatch");
  Buffer indirectOut(lpv_shade_indirect_diffuse, objectId.extent);
  Buffer colorOut(lpv_shade_color, objectId.extent);
  readWords(gl, indirect.get(), indirectOut);
  readWords(gl, color.get(), colorOut);
  if (ctx.plan.on(Effect::direct_light)) {
    Buffer diffuseOut(lpv_shade_direct_diffuse, objectId.extent);
    Buffer specularOut(lpv_shade_direct_specular, objectId.extent);
    readWords(gl, directDiffuse.get(), diffuseOut);
    readWords(gl, directSpecular.get(), specularOut);
    buffers.put(std::move(diffuseOut));
    buffers.put(std::move(specularOut));
  }
  gl.check("shade: reading back");
  buffers.put(std::move(indirectOut));
  buffers.put(std::move(colorOut));
}

}  // namespace voxgi::gpu
