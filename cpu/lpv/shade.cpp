// CPU shade stage: per pixel, the accumulated volume's irradiance and the analytic lights'
// direct light with the RSM depth as shadow map (shaders/shared/lpv/shade_kernel.h), then the
// final colour with the shared compose kernel (no indirect specular: the volume carries diffuse
// light only).
#include <tbb/blocked_range.h>

#include "common/gbuffer.h"
#include "common/lpv/propagate.h"
#include "common/lpv/rsm.h"
#include "common/lpv/sh_buffers.h"
#include "common/parallel.h"
#include "cpu/stages.h"
#include "shaders/shared/compose.h"
#include "shaders/shared/lpv/shade_kernel.h"

namespace voxgi::cpu {
namespace {

struct ShadeVolumes {
  const Buffer& accumulated;
  const GridSpec& grid;
  const std::vector<shared::LightData>& lights;
  const voxgi::lpv::RsmSetup& rsm;
  const Buffer* depth;  // the rsm stage's, when it ran
  float accumulatedAt(glm::ivec3 cell, int word) const {
    const int n = grid.resolution;
    if (glm::any(glm::lessThan(cell, glm::ivec3(0))) ||
        glm::any(glm::greaterThanEqual(cell, glm::ivec3(n))))
      return 0.0f;
    return accumulated.get<float>(grid.index(cell), word);
  }
  shared::LightData lightAt(int i) const { return lights[size_t(i)]; }
  shared::RsmView rsmViewAt(int i) const { return rsm.views[size_t(i)]; }
  float rsmDepthAt(int view, glm::ivec2 texel) const {
    const auto r = size_t(rsm.params.resolution);
    return depth->get<float>((size_t(view) * r + size_t(texel.y)) * r + size_t(texel.x), 0);
  }
};

}  // namespace

void lpv::shade(const StageContext& ctx, BufferSet& buffers) {
  checkStageMemory(ctx, StageId::lpv_shade);
  using enum BufferId;
  const voxgi::lpv::ShBuffers sh = voxgi::lpv::shBuffers(ctx.settings.lpv);
  const voxgi::lpv::RsmSetup rsm = voxgi::lpv::prepareRsm(ctx.scene, ctx.settings);
  const ShadeVolumes volumes{buffers.at(sh.accumulated), ctx.scene.grid, rsm.lights, rsm,
                             buffers.find(lpv_rsm_depth)};
  const shared::ShadeParams params = voxgi::lpv::shadeParams(ctx);
  const GbufferView gbuffer(buffers);
  const Buffer &objectId = gbuffer.objectId, &position = gbuffer.position, &normal = gbuffer.normal,
               &albedo = gbuffer.albedo, &specular = gbuffer.specular, *emission = gbuffer.emission;
  const bool direct = ctx.plan.on(Effect::direct_light);
  Buffer directDiffuse = direct ? Buffer(lpv_shade_direct_diffuse, objectId.extent) : Buffer();
  Buffer directSpecular = direct ? Buffer(lpv_shade_direct_specular, objectId.extent) : Buffer();
  Buffer indirect(lpv_shade_indirect_diffuse, objectId.extent);
  Buffer color(lpv_shade_color, objectId.extent);
  const int width = objectId.extent.x;
  parallelFor(tbb::blocked_range<int>(0, objectId.extent.y), [&](const auto& rows) {
    for (int y = rows.begin(); y != rows.end(); ++y)
      for (int x = 0; x < width; ++x) {
        const size_t e = size_t(y) * size_t(width) + size_t(x);
        const uint32_t id = objectId.get<uint32_t>(e, 0);
        const glm::vec3 zero(0.0f);
        glm::vec3 e3 = zero, diffuse = zero, glossy = zero;
        if (id != 0) {
          const glm::vec3 p = position.vec3At(e), n = normal.vec3At(e);
          e3 = shared::lpvIrradiance(volumes, p, n, params);
          shared::lpvDirect(volumes, p, n, specular.get<float>(e, 3), params, rsm.params, diffuse,
                            glossy);
        }
        indirect.setVec3(e, e3);
        if (direct) {
          directDiffuse.setVec3(e, diffuse);
          directSpecular.setVec3(e, glossy);
        }
        color.setVec3(
            e, shared::composePixel(id, albedo.vec3At(e), specular.vec3At(e),
                                    emission == nullptr ? zero : emission->vec3At(e), diffuse,
                                    glossy, e3, zero, 0.0f, ctx.scene.background));
      }
  });
  if (direct) {
    buffers.put(std::move(directDiffuse));
    buffers.put(std::move(directSpecular));
  }
  buffers.put(std::move(indirect));
  buffers.put(std::move(color));
}

}  // namespace voxgi::cpu
