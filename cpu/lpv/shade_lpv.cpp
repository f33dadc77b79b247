// CPU shade_lpv stage: per pixel, the accumulated volume's irradiance
// (shaders/shared/lpv/shade_kernel.h), then the final colour with VCT's compose kernel (no
// specular term: the volume carries diffuse light only).
#include <tbb/blocked_range.h>

#include "common/lpv/propagation.h"
#include "common/lpv/sh_buffers.h"
#include "common/parallel.h"
#include "cpu/stages.h"
#include "shaders/shared/lpv/shade_kernel.h"
#include "shaders/shared/compose_kernel.h"

namespace voxgi::cpu {
namespace {

struct ShadeVolumes {
  const Buffer& accumulated;
  const GridSpec& grid;
  float accumulatedAt(glm::ivec3 cell, int word) const {
    const int n = grid.resolution;
    if (glm::any(glm::lessThan(cell, glm::ivec3(0))) ||
        glm::any(glm::greaterThanEqual(cell, glm::ivec3(n))))
      return 0.0f;
    return accumulated.get<float>(grid.index(cell), word);
  }
};

}  // namespace

void lpv::shade_lpv(const StageContext& ctx, BufferSet& buffers) {
  checkStageMemory(ctx, StageId::lpv_shade_lpv);
  using enum BufferId;
  const voxgi::lpv::ShBuffers sh = voxgi::lpv::shBuffers(ctx.settings.lpv);
  const ShadeVolumes volumes{buffers.at(sh.accumulated), ctx.scene.grid};
  const shared::ShadeParams params = voxgi::lpv::shadeParams(ctx);
  const Buffer& objectId = buffers.at(common_gbuffer_object_id);
  const Buffer &position = buffers.at(common_gbuffer_pixel_position),
               &normal = buffers.at(common_gbuffer_pixel_normal),
               &albedo = buffers.at(common_gbuffer_pixel_albedo),
               *emission = buffers.find(common_gbuffer_pixel_emission);
  Buffer indirect(lpv_shade_lpv_indirect_diffuse, objectId.extent);
  Buffer color(lpv_shade_lpv_color, objectId.extent);
  const int width = objectId.extent.x;
  parallelFor(tbb::blocked_range<int>(0, objectId.extent.y), [&](const auto& rows) {
    for (int y = rows.begin(); y != rows.end(); ++y)
      for (int x = 0; x < width; ++x) {
        const size_t e = size_t(y) * size_t(width) + size_t(x);
        const uint32_t id = objectId.get<uint32_t>(e, 0);
        const glm::vec3 e3 =
            id == 0 ? glm::vec3(0.0f)
                    : shared::lpvIrradiance(volumes, position.vec3At(e), normal.vec3At(e), params);
        indirect.setVec3(e, e3);
        const glm::vec3 zero(0.0f);
        color.setVec3(e, shared::composePixel(id, albedo.vec3At(e), zero,
                                              emission == nullptr ? zero : emission->vec3At(e),
                                              zero, zero, e3, zero, 0.0f, ctx.scene.background));
      }
  });
  buffers.put(std::move(indirect));
  buffers.put(std::move(color));
}

}  // namespace voxgi::cpu
