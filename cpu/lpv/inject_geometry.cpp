// CPU inject_geometry stage: the shared kernel (shaders/shared/lpv/inject_geometry_kernel.h) per
// geometry-volume cell, a gather over voxelize's sums: each cell is written by one task.
#include <tbb/blocked_range.h>

#include "common/parallel.h"
#include "cpu/stages.h"
#include "shaders/shared/lpv/inject_geometry_kernel.h"

namespace voxgi::cpu {
namespace {

struct SurfaceVolumes {
  const Buffer& weight;  // voxelize.weight_sum
  const Buffer& normal;  // voxelize.normal_sum
  const GridSpec& grid;
  glm::vec4 surfaceAt(glm::ivec3 v) const {
    const int n = grid.resolution;
    if (glm::any(glm::lessThan(v, glm::ivec3(0))) ||
        glm::any(glm::greaterThanEqual(v, glm::ivec3(n))))
      return glm::vec4(0.0f);
    const size_t e = grid.index(v);
    return {float(weight.get<uint32_t>(e, 0)), float(normal.get<int32_t>(e, 0)),
            float(normal.get<int32_t>(e, 1)), float(normal.get<int32_t>(e, 2))};
  }
};

}  // namespace

void lpv::inject_geometry(const StageContext& ctx, BufferSet& buffers) {
  checkStageMemory(ctx, StageId::lpv_inject_geometry);
  const int n = ctx.scene.grid.resolution;
  const SurfaceVolumes volumes{buffers.at(BufferId::common_voxelize_weight_sum),
                               buffers.at(BufferId::common_voxelize_normal_sum), ctx.scene.grid};
  Buffer blocking(BufferId::lpv_inject_geometry_blocking, glm::ivec3(n));
  parallelFor(tbb::blocked_range<int>(0, n * n), [&](const auto& rows) {
    for (int row = rows.begin(); row != rows.end(); ++row)
      for (int x = 0; x < n; ++x) {
        const glm::ivec3 g(x, row % n, row / n);
        const glm::vec4 b = shared::cornerBlocking(volumes, g);
        const size_t e = ctx.scene.grid.index(g);
        for (int c = 0; c < 4; ++c) blocking.set(e, c, b[c]);
      }
  });
  buffers.put(std::move(blocking));
}

}  // namespace voxgi::cpu
