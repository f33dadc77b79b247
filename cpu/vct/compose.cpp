// CPU compose stage: the shared kernel (shaders/shared/compose.h) per pixel.
#include <optional>

#include <tbb/blocked_range.h>

#include "common/parallel.h"
#include "common/technique.h"
#include "cpu/stages.h"
#include "shaders/shared/compose.h"

namespace voxgi::cpu {
void vct::compose(const StageContext& ctx, BufferSet& buffers) {
  checkStageMemory(ctx, StageId::vct_compose);
  using enum BufferId;
  const Buffer& objectId = buffers.at(common_gbuffer_object_id);
  // AO is applied only where the technique's light terms say so (plan.mode=full computes it
  // whether asked for or not).
  const std::optional<BufferId> ao = ctx.technique.lightTerms(ctx.settings).ambientOcclusion;
  const Buffer* ambient = ao ? buffers.find(*ao) : nullptr;
  const Buffer *albedo = buffers.find(common_gbuffer_pixel_albedo),
               *specular = buffers.find(common_gbuffer_pixel_specular),
               *emission = buffers.find(common_gbuffer_pixel_emission),
               *directDiffuse = buffers.find(vct_trace_cones_direct_diffuse),
               *directSpecular = buffers.find(vct_trace_cones_direct_specular),
               *indirectDiffuse = buffers.find(vct_trace_cones_indirect_diffuse),
               *indirectSpecular = buffers.find(vct_trace_cones_indirect_specular);
  Buffer color(BufferId::vct_compose_color, objectId.extent);
  const int width = objectId.extent.x;
  parallelFor(tbb::blocked_range<int>(0, objectId.extent.y), [&](const auto& rows) {
    for (int y = rows.begin(); y != rows.end(); ++y)
      for (int x = 0; x < width; ++x) {
        const size_t e = size_t(y) * size_t(width) + size_t(x);
        const glm::vec3 c = shared::composePixel(
            objectId.get<uint32_t>(e, 0), vec3AtOr0(albedo, e), vec3AtOr0(specular, e),
            vec3AtOr0(emission, e), vec3AtOr0(directDiffuse, e), vec3AtOr0(directSpecular, e),
            vec3AtOr0(indirectDiffuse, e), vec3AtOr0(indirectSpecular, e),
            ambient == nullptr ? 0.0f : ambient->get<float>(e, 0), ctx.scene.background);
        color.setVec3(e, c);
      }
  });
  buffers.put(std::move(color));
}

}  // namespace voxgi::cpu
