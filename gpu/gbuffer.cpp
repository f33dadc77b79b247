// GPU gbuffer stage: rasterizes the voxel-local triangles, then the point clouds' discs
// (shaders/gbuffer_disc.vert), into float and integer render targets (one per buffer) with a depth
// test, then reads them back. The projection flips y so GL row 0 is image row 0, and pixel centres
// are the CPU rays' (common/camera_geometry.h).
#include <iterator>

#include "common/camera_geometry.h"
#include "gpu/program.h"
#include "gpu/stages.h"
#include "gpu/surface_raster.h"
#include "gpu/texture_pool.h"
#include "gpu/volumes.h"

namespace voxgi::gpu {
namespace {

// Colour attachment i holds kTargets[i].
constexpr RasterTarget kTargets[] = {{BufferId::common_gbuffer_pixel_position, GL_RGBA32F},
                                     {BufferId::common_gbuffer_pixel_normal, GL_RGBA32F},
                                     {BufferId::common_gbuffer_pixel_albedo, GL_RGBA32F},
                                     {BufferId::common_gbuffer_pixel_specular, GL_RGBA32F},
                                     {BufferId::common_gbuffer_pixel_emission, GL_RGBA32F},
                                     {BufferId::common_gbuffer_object_id, GL_R32UI},
                                     {BufferId::common_gbuffer_primitive_id, GL_R32UI}};

}  // namespace

void common::gbuffer(GlContext& context, const StageContext& ctx, BufferSet& buffers) {
  const Gl& gl = beginStage(context, ctx, StageId::common_gbuffer);
  const CameraGeometry g = prepareCameraGeometry(ctx.scene);
  const CameraRays& cam = g.camera;
  const int w = cam.width, h = cam.height;
  SurfaceRaster raster(gl, ctx.scene, g, kTargets, {w, h});
  const glm::mat4 viewProjection = cam.viewProjection(kGbufferNearPlane, g.farPlane);
  const auto setCamera = [&](Program& program) {
    program.set("uViewProjection", viewProjection);
    program.set("uForward", cam.forward);
    program.set("uRight", cam.right);
    program.set("uUp", cam.up);
    program.set("uTanHalfFov", cam.tanHalfFov);
    program.set("uAspect", cam.aspect);
    program.set("uSize", glm::vec2(float(w), float(h)));
    program.set("uOrigin", cam.origin);
  };
  const TexturePoolBuffers textures(gl, ctx.scene.textures);
  Program program(gl, {&shaders::gbuffer_vert, &shaders::gbuffer_frag});
  setCamera(program);
  program.set("uPixelSide", cam.pixelSide());
  program.use();
  raster.begin();
  raster.drawLayer(0);
  if (!g.discs.empty()) {
    GlBuffer discs(gl, createBuffer(gl, g.discs.size() * sizeof(SurfaceDisc), g.discs.data()));
    Program discProgram(gl, {&shaders::gbuffer_disc_vert, &shaders::gbuffer_disc_frag});
    setCamera(discProgram);
    discProgram.set("uTriangleCount", unsigned(g.triangles.size()));
    discProgram.use();
    gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, discs.get());
    gl.DrawArrays(GL_TRIANGLES, 0, GLsizei(6 * g.discs.size()));
  }
  raster.end();
  gl.check("gbuffer: rasterizing");
  for (size_t i = 0; i < std::size(kTargets); ++i)
    if (bufferNeeded(bufferSpec(kTargets[i].buffer), ctx.plan)) buffers.put(raster.read(i));
  gl.check("gbuffer: reading back");
}

}  // namespace voxgi::gpu
