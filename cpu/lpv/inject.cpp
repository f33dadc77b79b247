// CPU inject stage: every VPL's lobe (shaders/shared/lpv/inject_kernel.h), the emitters' and
// one per RSM texel that saw a surface (shaders/shared/lpv/rsm_kernel.h), added to its cell with
// integer atomics, so the sums are the same for any thread count and order.
#include <atomic>

#include <tbb/blocked_range.h>

#include "common/lpv/inject.h"
#include "common/lpv/rsm.h"
#include "common/lpv/sh_buffers.h"
#include "common/parallel.h"
#include "cpu/stages.h"
#include "shaders/shared/lpv/inject_kernel.h"
#include "shaders/shared/lpv/rsm_kernel.h"

namespace voxgi::cpu {

void lpv::inject(const StageContext& ctx, BufferSet& buffers) {
  const voxgi::lpv::ShBuffers sh = voxgi::lpv::shBuffers(ctx.settings.lpv);
  checkStageMemory(ctx, StageId::lpv_inject);
  const voxgi::lpv::Injection injection = voxgi::lpv::prepareInjection(ctx);
  const int n = ctx.scene.grid.resolution, coefficients = injection.params.coefficients;
  Buffer sums(sh.intensitySum, glm::ivec3(n));
  const auto add = [&](const shared::Vpl& vpl) {
    const glm::ivec3 cell = shared::vplCell(vpl);
    if (glm::any(glm::lessThan(cell, glm::ivec3(0))) ||
        glm::any(glm::greaterThanEqual(cell, glm::ivec3(n))))
      return;  // outside the grid: its light is lost
    const size_t first = ctx.scene.grid.index(cell) * size_t(3 * coefficients);
    for (int c = 0; c < 3; ++c)
      for (int i = 0; i < coefficients; ++i) {
        const int q = shared::vplCoefficient(vpl, c, i, injection.params.scale);
        if (q == 0) continue;
        std::atomic_ref<uint32_t>(sums.words[first + size_t(c * coefficients + i)])
            .fetch_add(static_cast<uint32_t>(q), std::memory_order_relaxed);
      }
  };
  const auto& vpls = injection.vpls;
  parallelFor(tbb::blocked_range<size_t>(0, vpls.size()), [&](const auto& range) {
    for (size_t v = range.begin(); v != range.end(); ++v) add(vpls[v]);
  });
  if (ctx.plan.runs(StageId::lpv_rsm)) {
    const voxgi::lpv::RsmSetup rsm = voxgi::lpv::prepareRsm(ctx.scene, ctx.settings);
    const Buffer &flux = buffers.at(BufferId::lpv_rsm_flux),
                 &normal = buffers.at(BufferId::lpv_rsm_normal),
                 &depth = buffers.at(BufferId::lpv_rsm_depth);
    const int r = rsm.params.resolution;
    const bool shift = injection.params.shiftRsmVpls == 1;
    parallelFor(0, flux.extent.y, [&](int row) {
      const shared::RsmView& view = rsm.views[size_t(row / r)];
      for (int x = 0; x < r; ++x) {
        const size_t e = size_t(row) * size_t(r) + size_t(x);
        const float t = depth.get<float>(e, 0);
        if (t == 0.0f) continue;
        add(shared::rsmVpl(view, {x, row % r}, r, t, normal.vec3At(e), flux.vec3At(e), shift));
      }
    });
  }
  buffers.put(std::move(sums));
}

}  // namespace voxgi::cpu
