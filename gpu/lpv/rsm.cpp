// GPU rsm stage: rasterizes the voxel-local triangles from every view (shaders/lpv/rsm.vert,
// rsm.frag) into one layer per view (gpu/surface_raster.h), then reads the layers back one below
// another. The projection flips y so GL row 0 is texel row 0, and fragment centres are the CPU's
// texel rays (common/lpv/rsm.h).
#include <iterator>
#include <string>
#include <vector>

#include "common/camera_geometry.h"
#include "common/error.h"
#include "common/lpv/rsm.h"
#include "gpu/program.h"
#include "gpu/stages.h"
#include "gpu/surface_raster.h"
#include "gpu/texture_pool.h"
#include "gpu/volumes.h"

namespace voxgi::gpu {
namespace {

// Colour attachment i holds kTargets[i].
constexpr RasterTarget kTargets[] = {{BufferId::lpv_rsm_flux, GL_RGBA32F},
                                     {BufferId::lpv_rsm_normal, GL_RGBA32F},
                                     {BufferId::lpv_rsm_depth, GL_RGBA32F},
                                     {BufferId::lpv_rsm_primitive_id, GL_R32UI}};

// Refuses maps the GL implementation cannot hold, naming the setting that sizes them.
void requireMapSize(const Gl& gl, const StageContext& ctx, int resolution, int views) {
  GLint side = 0, layers = 0;
  gl.GetIntegerv(GL_MAX_TEXTURE_SIZE, &side);
  gl.GetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &layers);
  if (resolution > side)
    throw InputError(ctx.scene.file, "rsm.resolution",
                     std::to_string(resolution) +
                         " texels is more than this GL's largest texture (" + std::to_string(side) +
                         ")");
  if (views > layers)
    throw InputError(ctx.scene.file, "lights",
                     std::to_string(views) + " shadow-map views are more than this GL's " +
                         std::to_string(layers) + " texture layers");
}

}  // namespace

void lpv::rsm(GlContext& context, const StageContext& ctx, BufferSet& buffers) {
  const Gl& gl = beginStage(context, ctx, StageId::lpv_rsm);
  const voxgi::lpv::RsmSetup setup = voxgi::lpv::prepareRsm(ctx.scene, ctx.settings);
  const int r = setup.params.resolution, views = setup.params.viewCount;
  requireMapSize(gl, ctx, r, views);
  const CameraGeometry g = prepareCameraGeometry(ctx.scene);
  const std::vector<shared::LightData>& lights = setup.lights;
  SurfaceRaster raster(gl, ctx.scene, g, kTargets, {r, r}, views);
  GlBuffer viewBlock(gl, createBlock(gl, setup.params, setup.views));
  GlBuffer lightBlock(gl,
                      createBuffer(gl, lights.size() * sizeof(shared::LightData), lights.data()));
  const TexturePoolBuffers textures(gl, ctx.scene.textures);
  Program program(gl, {&shaders::lpv_rsm_vert, &shaders::lpv_rsm_frag});
  program.use();
  raster.begin();
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, viewBlock.get());
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 4, lightBlock.get());
  const float farPlane = voxgi::lpv::rsmFarPlane(ctx.scene, setup);
  for (int v = 0; v < views; ++v) {
    program.set("uViewProjection", voxgi::lpv::rsmViewProjection(setup.views[size_t(v)], farPlane));
    program.set("uView", v);
    raster.drawLayer(v);
  }
  raster.end();
  gl.check("rsm: rasterizing");
  for (size_t i = 0; i < std::size(kTargets); ++i) buffers.put(raster.read(i));
  gl.check("rsm: reading back");
}

}  // namespace voxgi::gpu
