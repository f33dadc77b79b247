// CPU inject_geometry stage: the shared kernel (shaders/shared/lpv/inject_geometry_kernel.h) per
// geometry-volume cell, a gather over voxelize's sums: each cell is written by one task. With
// inject_geometry.blockers=rsm, per light a scatter of its RSM texels' surfaces with integer
// atomics, the light whose sum has the larger area kept per cell, then the same lobe per cell.
#include <atomic>

#include <tbb/blocked_range.h>

#include "common/lpv/rsm.h"
#include "common/parallel.h"
#include "cpu/stages.h"
#include "shaders/shared/lpv/inject_geometry_kernel.h"
#include "shaders/shared/lpv/rsm_kernel.h"

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

// The RSM texels' blockers: per light a scatter into `scratch`, then per cell the larger area.
Buffer rsmBlockers(const StageContext& ctx, const BufferSet& buffers) {
  const int n = ctx.scene.grid.resolution;
  const voxgi::lpv::RsmSetup rsm = voxgi::lpv::prepareRsm(ctx.scene, ctx.settings);
  Buffer sums(BufferId::lpv_inject_geometry_blocker_sum, glm::ivec3(n));
  if (!ctx.plan.runs(StageId::lpv_rsm)) return sums;
  const Buffer &depth = buffers.at(BufferId::lpv_rsm_depth),
               &normal = buffers.at(BufferId::lpv_rsm_normal);
  const int r = rsm.params.resolution;
  std::vector<uint32_t> scratch(sums.words.size());
  for (size_t first = 0; first < rsm.views.size(); first += size_t(rsm.views[first].viewCount)) {
    std::fill(scratch.begin(), scratch.end(), 0u);
    const int rows = r * rsm.views[first].viewCount;
    parallelFor(0, rows, [&](int row) {
      const shared::RsmView& view = rsm.views[first + size_t(row / r)];
      for (int x = 0; x < r; ++x) {
        const size_t e = (first * size_t(r) + size_t(row)) * size_t(r) + size_t(x);
        const float t = depth.get<float>(e, 0);
        if (t == 0.0f) continue;
        glm::ivec3 cell;
        const glm::ivec4 q = shared::rsmBlocker(view, {x, row % r}, r, t, normal.vec3At(e), cell);
        if (glm::any(glm::lessThan(cell, glm::ivec3(0))) ||
            glm::any(glm::greaterThanEqual(cell, glm::ivec3(n))))
          continue;
        const size_t w = 4 * ctx.scene.grid.index(cell);
        for (int c = 0; c < 4; ++c)
          std::atomic_ref<uint32_t>(scratch[w + size_t(c)])
              .fetch_add(static_cast<uint32_t>(q[c]), std::memory_order_relaxed);
      }
    });
    for (size_t w = 0; w < scratch.size(); w += 4)
      if (int32_t(scratch[w]) > int32_t(sums.words[w]))
        std::copy_n(scratch.begin() + std::ptrdiff_t(w), 4, sums.words.begin() + std::ptrdiff_t(w));
  }
  return sums;
}

}  // namespace

void lpv::inject_geometry(const StageContext& ctx, BufferSet& buffers) {
  checkStageMemory(ctx, StageId::lpv_inject_geometry);
  const int n = ctx.scene.grid.resolution;
  Buffer blocking(BufferId::lpv_inject_geometry_blocking, glm::ivec3(n));
  if (ctx.plan.on(Effect::rsm_blockers)) {
    Buffer sums = rsmBlockers(ctx, buffers);
    for (size_t e = 0; e < blocking.elementCount(); ++e) {
      const glm::vec4 s(float(sums.get<int32_t>(e, 0)), float(sums.get<int32_t>(e, 1)),
                        float(sums.get<int32_t>(e, 2)), float(sums.get<int32_t>(e, 3)));
      const glm::vec4 b = shared::rsmBlocking(s);
      for (int c = 0; c < 4; ++c) blocking.set(e, c, b[c]);
    }
    buffers.put(std::move(sums));
    buffers.put(std::move(blocking));
    return;
  }
  const SurfaceVolumes volumes{buffers.at(BufferId::common_voxelize_weight_sum),
                               buffers.at(BufferId::common_voxelize_normal_sum), ctx.scene.grid};
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
