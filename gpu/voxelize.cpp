// GPU voxelize stage: the graphics-pipeline voxelizer (conservative) or a compute splatter
// (antialiased) accumulate into integer images, a compute pass resolves them, and the volumes are
// read back for the next stage; the sums only where the plan keeps them (Effect::voxel_sums: for
// `voxgi diff`, a later stage or the next frame's update). In a sequence where few meshes moved,
// the images start from the frame before's sums and only the moved meshes' triangles are drawn,
// once subtracting that frame's and once adding this one's (common/voxelize_update.h).
#include <algorithm>
#include <optional>
#include <vector>

#include "common/effect_plan.h"
#include "common/error.h"
#include "common/voxel_overflow.h"
#include "common/voxelize_update.h"
#include "gpu/program.h"
#include "gpu/stages.h"
#include "gpu/texture_pool.h"
#include "gpu/volumes.h"
#include "shaders/shared/voxelize_layout.h"

namespace voxgi::gpu {

namespace {

// The integer images the triangles accumulate into (common/voxelize's fixed-point sums), bound
// as images 0-3; the emission sum only where the plan has emission.
struct SumImages {
  GlTexture weight, albedo, normal, emission;
};

// The sum images holding the frame before's sums (from the stash), for a partial update.
SumImages previousSums(const Gl& gl, int n, bool emissive, BufferSet& stash) {
  SumImages s{GlTexture(gl, createTexture3d(gl, GL_R32UI, glm::ivec3(n))),
              GlTexture(gl, createTexture3d(gl, GL_R32UI, {3 * n, n, n})),
              GlTexture(gl, createTexture3d(gl, GL_R32I, {3 * n, n, n})),
              GlTexture(gl, emissive ? createTexture3d(gl, GL_R32UI, {4 * n, n, n}) : 0)};
  const auto upload = [&](const GlTexture& t, BufferId id, int width, GLenum type) {
    const Buffer& b = stash.at(id);
    gl.TextureSubImage3D(t.get(), 0, 0, 0, 0, width * n, n, n, GL_RED_INTEGER, type,
                         b.words.data());
  };
  upload(s.weight, BufferId::common_voxelize_weight_sum, 1, GL_UNSIGNED_INT);
  upload(s.albedo, BufferId::common_voxelize_albedo_sum, 3, GL_UNSIGNED_INT);
  upload(s.normal, BufferId::common_voxelize_normal_sum, 3, GL_INT);
  if (emissive) upload(s.emission, BufferId::common_voxelize_emission_sum, 4, GL_UNSIGNED_INT);
  return s;
}

SumImages clearedSums(const Gl& gl, int n, bool emissive) {
  SumImages s{GlTexture(gl, createTexture3d(gl, GL_R32UI, glm::ivec3(n))),
              GlTexture(gl, createTexture3d(gl, GL_R32UI, {3 * n, n, n})),
              GlTexture(gl, createTexture3d(gl, GL_R32I, {3 * n, n, n})),
              GlTexture(gl, emissive ? createTexture3d(gl, GL_R32UI, {4 * n, n, n}) : 0)};
  const uint32_t zero = 0;
  for (GLuint t : {s.weight.get(), s.albedo.get(), s.emission.get()})
    if (t != 0) gl.ClearTexImage(t, 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
  gl.ClearTexImage(s.normal.get(), 0, GL_RED_INTEGER, GL_INT, &zero);
  return s;
}

void bindSums(const Gl& gl, const SumImages& s, GLenum access) {
  gl.BindImageTexture(0, s.weight.get(), 0, GL_TRUE, 0, access, GL_R32UI);
  gl.BindImageTexture(1, s.albedo.get(), 0, GL_TRUE, 0, access, GL_R32UI);
  gl.BindImageTexture(2, s.normal.get(), 0, GL_TRUE, 0, access, GL_R32I);
  if (s.emission.get() != 0)
    gl.BindImageTexture(3, s.emission.get(), 0, GL_TRUE, 0, access, GL_R32UI);
}

// Antialiased: one invocation per (triangle, row); see shaders/voxelize_antialiased.comp.
void splatAntialiased(const Gl& gl, const StageContext& ctx,
                      const std::vector<shared::VoxelTriangle>& tris, int n, bool emissive,
                      bool subtract) {
  std::vector<uint32_t> firstRow(tris.size() + 1, 0u);
  for (size_t i = 0; i < tris.size(); ++i) {
    if (uint64_t(firstRow[i]) + tris[i].subdivision > 0xFFFFFFFFull - 64u)
      throw InputError(ctx.scene.file, "meshes",
                       "too many antialiasing sample rows for one dispatch");
    firstRow[i + 1] = firstRow[i] + tris[i].subdivision;
  }
  GlBuffer rows(gl, createBuffer(gl, firstRow.size() * sizeof(uint32_t), firstRow.data()));
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, rows.get());
  Program splat(gl, {&shaders::voxelize_antialiased_comp});
  splat.set("uResolution", n);
  splat.set("uHasEmission", emissive ? 1 : 0);
  splat.set("uTriangleCount", static_cast<unsigned>(tris.size()));
  splat.set("uRowCount", firstRow.back());
  splat.set("uSubtract", subtract ? 1 : 0);
  splat.use();
  dispatchLinear(gl, firstRow.back());
}

// Conservative: the graphics pipeline, each triangle projected on its dominant axis.
void rasterizeConservative(const Gl& gl, size_t triangles, int n, bool emissive, bool subtract) {
  Program raster(gl, {&shaders::voxelize_vert, &shaders::voxelize_geom, &shaders::voxelize_frag});
  raster.set("uResolution", n);
  raster.set("uHasEmission", emissive ? 1 : 0);
  raster.set("uSubtract", subtract ? 1 : 0);
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
  gl.DrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(3 * triangles));
  gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
  gl.DeleteFramebuffers(1, &fbo);
  gl.DeleteVertexArrays(1, &vao);
}

// The float volumes the resolve pass writes from the sums (images 4-7).
struct ResolvedImages {
  GlTexture opacity, albedo, normal, emission;
};

ResolvedImages resolve(const Gl& gl, const StageContext& ctx, const SumImages& sums, int n,
                       bool emissive) {
  ResolvedImages r{GlTexture(gl, createTexture3d(gl, GL_R32F, glm::ivec3(n))),
                   GlTexture(gl, createTexture3d(gl, GL_R32F, {3 * n, n, n})),
                   GlTexture(gl, createTexture3d(gl, GL_R32F, {3 * n, n, n})),
                   GlTexture(gl, emissive ? createTexture3d(gl, GL_R32F, {3 * n, n, n}) : 0)};
  Program program(gl, {&shaders::voxelize_resolve_comp});
  program.set("uResolution", n);
  program.set("uHasEmission", emissive ? 1 : 0);
  program.set("uAntialiased", ctx.settings.voxelizeMode == VoxelizeMode::antialiased ? 1 : 0);
  program.set("uEmissionScale", ctx.triangles.emissionScale);
  program.set("uEmitterMean", ctx.settings.voxelizeEmission == VoxelizeEmission::emitters ? 1 : 0);
  bindSums(gl, sums, GL_READ_ONLY);
  gl.BindImageTexture(4, r.opacity.get(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_R32F);
  gl.BindImageTexture(5, r.albedo.get(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_R32F);
  gl.BindImageTexture(6, r.normal.get(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_R32F);
  if (emissive) gl.BindImageTexture(7, r.emission.get(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_R32F);
  program.use();
  const auto groups = static_cast<GLuint>((n + 3) / 4);
  gl.DispatchCompute(groups, groups, groups);
  gl.MemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
  gl.check("voxelize: resolving");
  return r;
}

void readBack(const Gl& gl, const SumImages& sums, const ResolvedImages& resolved, int n,
              bool keepSums, BufferSet& buffers) {
  auto read = [&](BufferId id, const GlTexture& texture, GLenum format, GLenum type) {
    Buffer b(id, glm::ivec3(n));
    readTexture(gl, texture.get(), 0, format, type, {b.components() * n, n, n}, b);
    buffers.put(std::move(b));
  };
  using enum BufferId;
  if (keepSums) {
    read(common_voxelize_weight_sum, sums.weight, GL_RED_INTEGER, GL_UNSIGNED_INT);
    read(common_voxelize_albedo_sum, sums.albedo, GL_RED_INTEGER, GL_UNSIGNED_INT);
    read(common_voxelize_normal_sum, sums.normal, GL_RED_INTEGER, GL_INT);
  }
  read(common_voxelize_opacity, resolved.opacity, GL_RED, GL_FLOAT);
  read(common_voxelize_albedo, resolved.albedo, GL_RED, GL_FLOAT);
  read(common_voxelize_normal, resolved.normal, GL_RED, GL_FLOAT);
  if (sums.emission.get() != 0) {
    if (keepSums)
      read(common_voxelize_emission_sum, sums.emission, GL_RED_INTEGER, GL_UNSIGNED_INT);
    read(common_voxelize_emission, resolved.emission, GL_RED, GL_FLOAT);
  }
  gl.check("voxelize: reading back");
}

}  // namespace

void common::voxelize(GlContext& context, const StageContext& ctx, BufferSet& buffers) {
  context.makeCurrent();
  const Gl& gl = context.gl();
  const int n = ctx.scene.grid.resolution;
  if (3 * n > context.max3dTextureSize())
    throw InputError(ctx.scene.file, "grid.resolution",
                     std::to_string(n) + " needs 3D images of width " + std::to_string(3 * n) +
                         ", above this GL's GL_MAX_3D_TEXTURE_SIZE " +
                         std::to_string(context.max3dTextureSize()));
  const bool emissive =
      ctx.plan.on(Effect::emission);  // emissionScale may be 0 under plan.mode=full
  const bool keepSums = ctx.plan.on(Effect::voxel_sums);
  // The GPU holds its sum images whether or not the plan reads them back: its images are the
  // stage's buffers with the sums, beside the read-back of the planned ones.
  EffectPlan withSums = ctx.plan;
  withSums.set(Effect::voxel_sums, true);
  finishVoxelSums(withSums);
  const double held = double(stageBufferBytes(StageId::common_voxelize, ctx.scene, withSums));
  const double planned = double(stageBufferBytes(StageId::common_voxelize, ctx.scene, ctx.plan));
  checkStageMemory(ctx, StageId::common_voxelize, 1.0 + held / planned);
  const bool antialiased = ctx.settings.voxelizeMode == VoxelizeMode::antialiased;
  refuseRepeatedTriangles(ctx.triangles, n, antialiased, ctx.scene.file);
  const std::optional<MovedTriangles> moved = movedTriangles(ctx, emissive);
  const uint32_t zero = 0;
  GlBuffer status(gl, createBuffer(gl, sizeof zero, &zero));
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, status.get());
  const TexturePoolBuffers textures(gl, ctx.scene.textures);
  const SumImages sums =
      moved ? previousSums(gl, n, emissive, ctx.previous->stash) : clearedSums(gl, n, emissive);
  bindSums(gl, sums, GL_READ_WRITE);
  gl.check("voxelize: allocating volumes");

  // Every triangle, or the moved meshes' of the frame before taken out, then this frame's added.
  const auto draw = [&](const std::vector<shared::VoxelTriangle>& tris, bool subtract) {
    if (tris.empty()) return;
    GlBuffer triangles(gl,
                       createBuffer(gl, tris.size() * sizeof(shared::VoxelTriangle), tris.data()));
    gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, triangles.get());
    if (antialiased)
      splatAntialiased(gl, ctx, tris, n, emissive, subtract);
    else
      rasterizeConservative(gl, tris.size(), n, emissive, subtract);
    gl.MemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT |
                     GL_SHADER_STORAGE_BARRIER_BIT);
    gl.check("voxelize: accumulating");
  };
  if (moved) {
    draw(trianglesIn(*ctx.previous->triangles, moved->before), true);
    draw(trianglesIn(ctx.triangles, moved->now), false);
  } else {
    draw(ctx.triangles.triangles, false);
  }
  const ResolvedImages resolved = resolve(gl, ctx, sums, n, emissive);

  uint32_t overflow = 0;
  gl.GetNamedBufferSubData(status.get(), 0, sizeof overflow, &overflow);
  if (overflow != 0)
    throw InputError(ctx.scene.file, "meshes",
                     "more than 32768 voxel faces of surface fall into one voxel (fixed-point "
                     "overflow); lower grid.resolution or remove overlapping copies");
  readBack(gl, sums, resolved, n, keepSums, buffers);
}

}  // namespace voxgi::gpu
