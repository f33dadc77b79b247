// GPU voxelize stage: the graphics-pipeline voxelizer (conservative) or a compute splatter
// (antialiased) accumulate into integer images, a compute pass resolves them, and every buffer is
// read back for the next stage and for `voxgi diff`.
#include <algorithm>
#include <vector>

#include "common/error.h"
#include "common/voxel_overflow.h"
#include "gpu/program.h"
#include "gpu/stages.h"
#include "gpu/volumes.h"
#include "shaders/shared/voxelize_layout.h"

namespace voxgi::gpu {

void common::voxelize(GlContext& context, const StageContext& ctx, BufferSet& buffers) {
  context.makeCurrent();
  const Gl& gl = context.gl();
  const int n = ctx.scene.grid.resolution;
  if (3 * n > context.max3dTextureSize())
    throw InputError(ctx.scene.file, "grid.resolution",
                     std::to_string(n) + " needs 3D images of width " + std::to_string(3 * n) +
                         ", above this GL's GL_MAX_3D_TEXTURE_SIZE " +
                         std::to_string(context.max3dTextureSize()));
  checkStageMemory(ctx, StageId::common_voxelize, 2.0);  // GPU copies plus the read-back buffers
  refuseRepeatedTriangles(ctx.triangles, n, ctx.settings.voxelizeMode == VoxelizeMode::antialiased,
                          ctx.scene.file);
  const bool antialiased = ctx.settings.voxelizeMode == VoxelizeMode::antialiased;
  const bool emissive =
      ctx.plan.on(Effect::emission);  // emissionScale may be 0 under plan.mode=full
  const auto& tris = ctx.triangles.triangles;

  GlBuffer triangles(gl,
                     createBuffer(gl, tris.size() * sizeof(shared::VoxelTriangle), tris.data()));
  const uint32_t zero = 0;
  GlBuffer status(gl, createBuffer(gl, sizeof zero, &zero));
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, triangles.get());
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, status.get());

  GlTexture weight(gl, createTexture3d(gl, GL_R32UI, glm::ivec3(n)));
  GlTexture albedoSum(gl, createTexture3d(gl, GL_R32UI, {3 * n, n, n}));
  GlTexture normalSum(gl, createTexture3d(gl, GL_R32I, {3 * n, n, n}));
  GlTexture emissionSum(gl, emissive ? createTexture3d(gl, GL_R32UI, {4 * n, n, n}) : 0);
  for (GLuint t : {weight.get(), albedoSum.get(), emissionSum.get()})
    if (t != 0) gl.ClearTexImage(t, 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
  gl.ClearTexImage(normalSum.get(), 0, GL_RED_INTEGER, GL_INT, &zero);
  gl.BindImageTexture(0, weight.get(), 0, GL_TRUE, 0, GL_READ_WRITE, GL_R32UI);
  gl.BindImageTexture(1, albedoSum.get(), 0, GL_TRUE, 0, GL_READ_WRITE, GL_R32UI);
  gl.BindImageTexture(2, normalSum.get(), 0, GL_TRUE, 0, GL_READ_WRITE, GL_R32I);
  if (emissive) gl.BindImageTexture(3, emissionSum.get(), 0, GL_TRUE, 0, GL_READ_WRITE, GL_R32UI);
  gl.check("voxelize: allocating volumes");

  if (!tris.empty()) {
    if (antialiased) {
      // One invocation per (triangle, row); see shaders/voxelize_antialiased.comp.
      std::vector<uint32_t> firstRow(tris.size() + 1, 0u);
      for (size_t i = 0; i < tris.size(); ++i) {
        if (uint64_t(firstRow[i]) + tris[i].info.y > 0xFFFFFFFFull - 64u)
          throw InputError(ctx.scene.file, "meshes",
                           "too many antialiasing sample rows for one dispatch");
        firstRow[i + 1] = firstRow[i] + tris[i].info.y;
      }
      GlBuffer rows(gl, createBuffer(gl, firstRow.size() * sizeof(uint32_t), firstRow.data()));
      gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, rows.get());
      Program splat(gl, {&shaders::voxelize_antialiased_comp});
      splat.set("uResolution", n);
      splat.set("uHasEmission", emissive ? 1 : 0);
      splat.set("uTriangleCount", static_cast<unsigned>(tris.size()));
      splat.set("uRowCount", firstRow.back());
      splat.use();
      dispatchLinear(gl, firstRow.back());
    } else {
      Program raster(gl,
                     {&shaders::voxelize_vert, &shaders::voxelize_geom, &shaders::voxelize_frag});
      raster.set("uResolution", n);
      raster.set("uHasEmission", emissive ? 1 : 0);
      raster.use();
      GLuint fbo = 0, vao = 0;
      gl.CreateFramebuffers(1, &fbo);  // no attachments: fragments only write images
      gl.NamedFramebufferParameteri(fbo, GL_FRAMEBUFFER_DEFAULT_WIDTH, n);
      gl.NamedFramebufferParameteri(fbo, GL_FRAMEBUFFER_DEFAULT_HEIGHT, n);
      gl.CreateVertexArrays(1, &vao);
      gl.BindFramebuffer(GL_FRAMEBUFFER, fbo);
      gl.BindVertexArray(vao);
      gl.Viewport(0, 0, n, n);
      gl.Disable(GL_DEPTH_TEST);
      gl.Disable(GL_CULL_FACE);
      gl.Disable(GL_MULTISAMPLE);
      gl.ColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
      gl.DrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(3 * tris.size()));
      gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
      gl.DeleteFramebuffers(1, &fbo);
      gl.DeleteVertexArrays(1, &vao);
    }
    gl.MemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT |
                     GL_SHADER_STORAGE_BARRIER_BIT);
    gl.check("voxelize: accumulating");
  }

  GlTexture opacity(gl, createTexture3d(gl, GL_R32F, glm::ivec3(n)));
  GlTexture albedo(gl, createTexture3d(gl, GL_R32F, {3 * n, n, n}));
  GlTexture normal(gl, createTexture3d(gl, GL_R32F, {3 * n, n, n}));
  GlTexture emission(gl, emissive ? createTexture3d(gl, GL_R32F, {3 * n, n, n}) : 0);
  {
    Program resolve(gl, {&shaders::voxelize_resolve_comp});
    resolve.set("uResolution", n);
    resolve.set("uHasEmission", emissive ? 1 : 0);
    resolve.set("uAntialiased", antialiased ? 1 : 0);
    resolve.set("uEmissionScale", ctx.triangles.emissionScale);
    resolve.set("uEmitterMean",
                ctx.settings.voxelizeEmission == VoxelizeEmission::emitters ? 1 : 0);
    gl.BindImageTexture(0, weight.get(), 0, GL_TRUE, 0, GL_READ_ONLY, GL_R32UI);
    gl.BindImageTexture(1, albedoSum.get(), 0, GL_TRUE, 0, GL_READ_ONLY, GL_R32UI);
    gl.BindImageTexture(2, normalSum.get(), 0, GL_TRUE, 0, GL_READ_ONLY, GL_R32I);
    if (emissive) gl.BindImageTexture(3, emissionSum.get(), 0, GL_TRUE, 0, GL_READ_ONLY, GL_R32UI);
    gl.BindImageTexture(4, opacity.get(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_R32F);
    gl.BindImageTexture(5, albedo.get(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_R32F);
    gl.BindImageTexture(6, normal.get(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_R32F);
    if (emissive) gl.BindImageTexture(7, emission.get(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_R32F);
    resolve.use();
    const auto groups = static_cast<GLuint>((n + 3) / 4);
    gl.DispatchCompute(groups, groups, groups);
    gl.MemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
    gl.check("voxelize: resolving");
  }

  uint32_t overflow = 0;
  gl.GetNamedBufferSubData(status.get(), 0, sizeof overflow, &overflow);
  if (overflow != 0)
    throw InputError(ctx.scene.file, "meshes",
                     "more than 32768 voxel faces of surface fall into one voxel (fixed-point "
                     "overflow); lower grid.resolution or remove overlapping copies");

  const glm::ivec3 extent(n);
  auto read = [&](BufferId id, GLuint texture, GLenum format, GLenum type) {
    Buffer b(id, extent);
    readTexture(gl, texture, 0, format, type, {b.components() * n, n, n}, b);
    buffers.put(std::move(b));
  };
  using enum BufferId;
  read(common_voxelize_weight_sum, weight.get(), GL_RED_INTEGER, GL_UNSIGNED_INT);
  read(common_voxelize_albedo_sum, albedoSum.get(), GL_RED_INTEGER, GL_UNSIGNED_INT);
  read(common_voxelize_normal_sum, normalSum.get(), GL_RED_INTEGER, GL_INT);
  read(common_voxelize_opacity, opacity.get(), GL_RED, GL_FLOAT);
  read(common_voxelize_albedo, albedo.get(), GL_RED, GL_FLOAT);
  read(common_voxelize_normal, normal.get(), GL_RED, GL_FLOAT);
  if (emissive) {
    read(common_voxelize_emission_sum, emissionSum.get(), GL_RED_INTEGER, GL_UNSIGNED_INT);
    read(common_voxelize_emission, emission.get(), GL_RED, GL_FLOAT);
  }
  gl.check("voxelize: reading back");
}

}  // namespace voxgi::gpu
