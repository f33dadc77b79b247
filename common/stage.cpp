#include "common/stage.h"

#include "common/error.h"
#include "common/memory.h"

namespace voxgi {

bool bufferNeeded(const BufferSpec& spec, const EffectPlan& plan) {
  if (!plan.runs(spec.stage)) return false;
  switch (spec.need) {
    case BufferNeed::always:
      return true;
    case BufferNeed::emission:
      return plan.emission;
    case BufferNeed::isotropic:
      return plan.mip == MipMode::isotropic;
    case BufferNeed::anisotropic:
      return plan.mip == MipMode::anisotropic;
    case BufferNeed::specular:
      return plan.specular;
    case BufferNeed::ambient_occlusion:
      return plan.ambientOcclusion;
  }
  return true;
}

uint64_t stageBufferBytes(std::string_view stage, const Scene& scene, const EffectPlan& plan) {
  const glm::ivec2 image(scene.camera.width, scene.camera.height);
  uint64_t words = 0;
  for (const BufferSpec* b : stageBuffers(stage))
    if (bufferNeeded(*b, plan))
      words += uint64_t(b->components) * shapeElements(b->shape, scene.grid.resolution, image);
  return 4u * words;
}

void checkStageMemory(const StageContext& ctx, std::string_view stage, double copies) {
  bool image = false;
  for (const BufferSpec* b : stageBuffers(stage)) image |= b->shape == BufferShape::image;
  const Scene& scene = ctx.scene;
  const auto bytes =
      static_cast<uint64_t>(copies * static_cast<double>(stageBufferBytes(stage, scene, ctx.plan)));
  const std::string what =
      image ? std::to_string(scene.camera.width) + "x" + std::to_string(scene.camera.height)
            : std::to_string(scene.grid.resolution) + "^3";
  requireMemory(bytes, "the " + std::string(stage) + " buffers at " + what, scene.file,
                image ? "camera.resolution" : "grid.resolution");
}

}  // namespace voxgi
