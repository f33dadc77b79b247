// CPU light_voxels stage: the shared kernel (shaders/shared/vct/light_voxels_kernel.h) per voxel.
// Each voxel is written by exactly one task, so the result does not depend on the thread count.
#include <tbb/blocked_range.h>

#include "common/parallel.h"
#include "common/vct/light_voxels.h"
#include "cpu/stages.h"

namespace voxgi::cpu {
namespace {

// The volumes the kernel reads (FETCH in the shared code).
struct LightVoxelsVolumes {
  const Buffer& opacity;
  const Buffer& albedo;
  const Buffer& normal;
  const Buffer* emission;
  const std::vector<shared::LightData>& lights;
  const GridSpec& grid;

  size_t index(glm::ivec3 v) const { return grid.index(v); }
  float opacityAt(glm::ivec3 v) const { return opacity.get<float>(index(v), 0); }
  glm::vec3 albedoAt(glm::ivec3 v) const { return albedo.vec3At(index(v)); }
  glm::vec3 normalAt(glm::ivec3 v) const { return normal.vec3At(index(v)); }
  glm::vec3 emissionAt(glm::ivec3 v) const { return emission->vec3At(index(v)); }
  shared::LightData lightAt(int i) const { return lights[size_t(i)]; }
};

}  // namespace

void vct::light_voxels(const StageContext& ctx, BufferSet& buffers) {
  checkStageMemory(ctx, StageId::vct_light_voxels);
  const int n = ctx.scene.grid.resolution;
  const Buffer* emission = buffers.find(BufferId::common_voxelize_emission);
  const LightVoxelsSetup setup = prepareLightVoxels(ctx, emission != nullptr);
  const LightVoxelsVolumes volumes{buffers.at(BufferId::common_voxelize_opacity),
                                   buffers.at(BufferId::common_voxelize_albedo),
                                   buffers.at(BufferId::common_voxelize_normal),
                                   emission,
                                   setup.lights,
                                   ctx.scene.grid};
  const shared::LightVoxelsUpdate update = lightVoxelsUpdate(ctx, setup, emission != nullptr);
  // A partial update starts from the frame before's radiance and relights only the voxels whose
  // inputs can have changed; a whole one rewrites every voxel of it (its pages stay mapped).
  Buffer radiance = ctx.previous != nullptr
                        ? ctx.previous->stash.take(BufferId::vct_light_voxels_radiance)
                        : Buffer{};
  if (radiance.spec == nullptr || radiance.extent != glm::ivec3(n))
    radiance = Buffer(BufferId::vct_light_voxels_radiance, glm::ivec3(n));
  parallelFor(tbb::blocked_range<int>(0, n * n), [&](const auto& rows) {
    for (int row = rows.begin(); row != rows.end(); ++row)
      for (int x = 0; x < n; ++x) {
        const glm::ivec3 v(x, row % n, row / n);
        if (update.partial == 1 && !shared::lightVoxelMayChange(volumes, v, setup.params, update))
          continue;
        const glm::vec4 r = shared::lightVoxel(volumes, v, setup.params);
        const size_t e = volumes.index(v);
        for (int c = 0; c < 4; ++c) radiance.set(e, c, r[c]);
      }
  });
  buffers.put(std::move(radiance));
}

}  // namespace voxgi::cpu
