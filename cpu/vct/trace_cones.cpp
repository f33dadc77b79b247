// CPU trace_cones stage: the shared kernel (shaders/shared/vct/trace_cones_kernel.h) per pixel.
// Each pixel is written by one task, so the image does not depend on the thread count.
#include <tbb/blocked_range2d.h>

#include "common/parallel.h"
#include "common/vct/kernel_params.h"
#include "common/vct/radiance_buffers.h"
#include "cpu/vct/cone_volumes.h"
#include "cpu/stages.h"
#include "shaders/shared/vct/trace_cones_kernel.h"

namespace voxgi::cpu {
void vct::trace_cones(const StageContext& ctx, BufferSet& buffers) {
  checkStageMemory(ctx, StageId::vct_trace_cones);
  const Scene& scene = ctx.scene;
  const int n = scene.grid.resolution;
  const ConeTraceSetup setup = prepareConeTrace(ctx);
  const RadianceBuffers lit = finalRadiance(ctx);
  const ConeVolumes volumes(buffers.at(lit.radiance), buffers.at(lit.pyramid), ctx.settings.vct.mip,
                            n, setup.lights, setup.cones);

  const Buffer& position = buffers.at(BufferId::common_gbuffer_pixel_position);
  const Buffer& normal = buffers.at(BufferId::common_gbuffer_pixel_normal);
  const Buffer& objectId = buffers.at(BufferId::common_gbuffer_object_id);
  const glm::ivec3 extent = position.extent;
  // The planned buffers of the stage, allocated; the others stay empty and are not written.
  const auto planned = [&](BufferId id) {
    return bufferNeeded(bufferSpec(id), ctx.plan) ? Buffer(id, extent) : Buffer();
  };
  Buffer directDiffuse = planned(BufferId::vct_trace_cones_direct_diffuse);
  Buffer indirectDiffuse = planned(BufferId::vct_trace_cones_indirect_diffuse);
  Buffer directSpecular = planned(BufferId::vct_trace_cones_direct_specular);
  Buffer indirectSpecular = planned(BufferId::vct_trace_cones_indirect_specular);
  Buffer ambient = planned(BufferId::vct_trace_cones_ambient_occlusion);

  // 8x8 tiles: neighbouring pixels' cones read the same voxels (cache), and small tasks balance
  // pixels of very different cost (background, early-terminating cones).
  const tbb::blocked_range2d<int> tiles(0, extent.y, 8, 0, extent.x, 8);
  parallelFor(tiles, [&](const tbb::blocked_range2d<int>& tile) {
    for (int y = tile.rows().begin(); y != tile.rows().end(); ++y)
      for (int x = tile.cols().begin(); x != tile.cols().end(); ++x) {
        const size_t e = size_t(y) * size_t(extent.x) + size_t(x);
        const uint32_t id = objectId.get<uint32_t>(e, 0);
        if (id == 0u) continue;  // background: every term stays 0
        const shared::PixelLight light = shared::tracePixel(
            volumes, position.vec3At(e), normal.vec3At(e), setup.objects.at(id), setup.params);
        directDiffuse.setVec3(e, light.directDiffuse);
        indirectDiffuse.setVec3(e, light.indirectDiffuse);
        if (directSpecular.spec != nullptr) directSpecular.setVec3(e, light.directSpecular);
        if (indirectSpecular.spec != nullptr) indirectSpecular.setVec3(e, light.indirectSpecular);
        if (ambient.spec != nullptr) ambient.set(e, 0, light.ambientOcclusion);
      }
  });
  for (Buffer* b : {&directDiffuse, &indirectDiffuse, &directSpecular, &indirectSpecular, &ambient})
    if (b->spec != nullptr) buffers.put(std::move(*b));
}

}  // namespace voxgi::cpu
