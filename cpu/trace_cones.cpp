// CPU trace_cones stage: the shared kernel (shaders/shared/trace_cones_kernel.h) per pixel. Each
// pixel is written by one task, so the image does not depend on the thread count.
#include <tbb/blocked_range2d.h>
#include <tbb/parallel_for.h>

#include "common/kernel_params.h"
#include "common/mips.h"
#include "cpu/cone_volumes.h"
#include "cpu/stages.h"
#include "shaders/shared/trace_cones_kernel.h"

namespace voxgi::cpu {
void trace_cones(const StageContext& ctx, BufferSet& buffers) {
  checkStageMemory(ctx, "trace_cones");
  const Scene& scene = ctx.scene;
  const int n = scene.grid.resolution;
  const ConeTraceSetup setup = prepareConeTrace(ctx);
  const ConeVolumes volumes(buffers.at("radiance"), buffers.at(pyramidName(ctx.plan.mip)),
                            ctx.plan.mip, n, setup.lights, setup.cones);

  const Buffer& position = buffers.at("pixel_position");
  const Buffer& normal = buffers.at("pixel_normal");
  const Buffer& objectId = buffers.at("object_id");
  const glm::ivec3 extent = position.extent;
  std::map<std::string, Buffer, std::less<>> out;
  for (const BufferSpec* spec : stageBuffers("trace_cones"))
    if (bufferNeeded(*spec, ctx.plan)) out[std::string(spec->name)] = Buffer(*spec, extent);
  const auto find = [&](const char* name) {
    const auto it = out.find(name);
    return it == out.end() ? nullptr : &it->second;
  };
  Buffer& directDiffuse = out.at("direct_diffuse");
  Buffer& indirectDiffuse = out.at("indirect_diffuse");
  Buffer* directSpecular = find("direct_specular");
  Buffer* indirectSpecular = find("indirect_specular");
  Buffer* ambient = find("ambient_occlusion");

  // 8x8 tiles: neighbouring pixels' cones read the same voxels (cache), and small tasks balance
  // pixels of very different cost (background, early-terminating cones).
  const tbb::blocked_range2d<int> tiles(0, extent.y, 8, 0, extent.x, 8);
  tbb::parallel_for(tiles, [&](const tbb::blocked_range2d<int>& tile) {
    for (int y = tile.rows().begin(); y != tile.rows().end(); ++y)
      for (int x = tile.cols().begin(); x != tile.cols().end(); ++x) {
        const size_t e = size_t(y) * size_t(extent.x) + size_t(x);
        const uint32_t id = objectId.get<uint32_t>(e, 0);
        if (id == 0u) continue;  // background: every term stays 0
        const shared::PixelLight light = shared::tracePixel(
            volumes, position.vec3At(e), normal.vec3At(e), setup.objects.at(id), setup.params);
        directDiffuse.setVec3(e, light.directDiffuse);
        indirectDiffuse.setVec3(e, light.indirectDiffuse);
        if (directSpecular != nullptr) directSpecular->setVec3(e, light.directSpecular);
        if (indirectSpecular != nullptr) indirectSpecular->setVec3(e, light.indirectSpecular);
        if (ambient != nullptr) ambient->set(e, 0, light.ambientOcclusion);
      }
  });
  for (auto& [name, buffer] : out) buffers[name] = std::move(buffer);
}

}  // namespace voxgi::cpu
