#include "common/stage.h"

#include "common/error.h"
#include "common/memory.h"

namespace voxgi {

uint64_t stageBufferBytes(StageId stage, const Scene& scene, const EffectPlan& plan) {
  const glm::ivec2 image(scene.camera.width, scene.camera.height);
  uint64_t bytes = 0;
  for (const BufferSpec* b : stageBuffers(stageSpec(stage)))
    if (bufferNeeded(*b, plan))
      bytes += uint64_t(b->components) * (b->type == ScalarType::f16 ? 2u : 4u) *
               shapeElements(b->shape, scene.grid.resolution, image, plan.seriesLength, plan.maps);
  return bytes;
}

void checkStageMemory(const StageContext& ctx, StageId stage, double copies) {
  bool image = false, maps = false;
  for (const BufferSpec* b : stageBuffers(stageSpec(stage))) {
    image |= b->shape == BufferShape::image;
    maps |= b->shape == BufferShape::maps;
  }
  const Scene& scene = ctx.scene;
  const auto bytes =
      static_cast<uint64_t>(copies * static_cast<double>(stageBufferBytes(stage, scene, ctx.plan)));
  const glm::ivec2 m = ctx.plan.maps;
  const std::string what =
      maps    ? std::to_string(m.y) + " maps of " + std::to_string(m.x) + "^2"
      : image ? std::to_string(scene.camera.width) + "x" + std::to_string(scene.camera.height)
              : std::to_string(scene.grid.resolution) + "^3";
  requireMemory(bytes, "the " + std::string(stageSpec(stage).name) + " buffers at " + what,
                scene.file,
                maps    ? "rsm.resolution"
                : image ? "camera.resolution"
                        : "grid.resolution");
}

void putDarkOutputs(const StageContext& ctx, StageId stage, BufferSet& buffers) {
  checkStageMemory(ctx, stage);
  const Scene& scene = ctx.scene;
  for (const BufferSpec* b : stageBuffers(stageSpec(stage)))
    if (bufferNeeded(*b, ctx.plan))
      buffers.put(Buffer(b->id, shapeExtent(b->shape, scene.grid.resolution,
                                            {scene.camera.width, scene.camera.height},
                                            ctx.plan.seriesLength, ctx.plan.maps)));
}

}  // namespace voxgi
