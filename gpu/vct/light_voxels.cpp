// GPU light_voxels stage: shaders/vct/light_voxels.comp runs the shared kernel per voxel on the
// voxelize buffers uploaded as textures (and, in a partial update, the frame before's radiance);
// the radiance volume is read back.
#include "common/vct/light_voxels.h"
#include "gpu/program.h"
#include "gpu/stages.h"
#include "gpu/volumes.h"

namespace voxgi::gpu {

void vct::light_voxels(GlContext& context, const StageContext& ctx, BufferSet& buffers) {
  const Gl& gl = beginStage(context, ctx, StageId::vct_light_voxels);
  const int n = ctx.scene.grid.resolution;
  const Buffer* emission = buffers.find(BufferId::common_voxelize_emission);
  // Under emitters.mode=area_lights the emission volume is not read, so not uploaded.
  const LightVoxelsSetup setup = prepareLightVoxels(ctx, emission != nullptr);
  const bool emissive = setup.params.emissive == 1;

  GlBuffer lightBlock(gl, createBlock(gl, setup.params, setup.lights));
  GlTexture opacity(gl, uploadVolume(gl, buffers.at(BufferId::common_voxelize_opacity)));
  GlTexture albedo(gl, uploadVolume(gl, buffers.at(BufferId::common_voxelize_albedo)));
  GlTexture normal(gl, uploadVolume(gl, buffers.at(BufferId::common_voxelize_normal)));
  GlTexture emissionTexture(gl, emissive ? uploadVolume(gl, *emission) : 0);
  GlTexture radiance(gl, createVolume(gl, 4, glm::ivec3(n)));
  // A partial update copies the frame before's radiance where lightVoxelMayChange says no.
  const shared::LightVoxelsUpdate update = lightVoxelsUpdate(ctx, setup, emission != nullptr);
  GlBuffer updateBlock(gl, createBuffer(gl, sizeof update, &update));
  GlTexture previous(
      gl, update.partial == 1
              ? uploadVolume(gl, ctx.previous->stash.at(BufferId::vct_light_voxels_radiance))
              : 0);

  Program program(gl, {&shaders::vct_light_voxels_comp});
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, lightBlock.get());
  gl.BindTextureUnit(0, opacity.get());
  gl.BindTextureUnit(1, albedo.get());
  gl.BindTextureUnit(2, normal.get());
  gl.BindTextureUnit(3, emissionTexture.get());
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, updateBlock.get());
  gl.BindTextureUnit(4, previous.get());
  gl.BindImageTexture(0, radiance.get(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  program.use();
  const auto groups = static_cast<GLuint>((n + 3) / 4);
  gl.DispatchCompute(groups, groups, groups);
  gl.MemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);
  gl.check("light_voxels: dispatch");

  Buffer out(BufferId::vct_light_voxels_radiance, glm::ivec3(n));
  readVolume(gl, radiance.get(), 0, glm::ivec3(n), out);
  gl.check("light_voxels: reading back");
  buffers.put(std::move(out));
}

}  // namespace voxgi::gpu
