#include "common/stage.h"

#include "common/error.h"
#include "common/memory.h"

namespace voxgi {

bool bufferNeeded(const BufferSpec& spec, const Scene& scene, const Settings& settings) {
  switch (spec.need) {
    case BufferNeed::always:
      return true;
    case BufferNeed::emission:
      return scene.hasEmission();
    case BufferNeed::isotropic:
      return settings.mip == MipMode::isotropic;
    case BufferNeed::anisotropic:
      return settings.mip == MipMode::anisotropic;
    case BufferNeed::glossy:
      return scene.hasGlossy();
    case BufferNeed::ambient_occlusion:
      return settings.ambientOcclusion == AmbientOcclusion::on;
  }
  return true;
}

uint64_t stageBufferBytes(std::string_view stage, const Scene& scene, const Settings& settings) {
  const glm::ivec2 image(scene.camera.width, scene.camera.height);
  uint64_t words = 0;
  for (const BufferSpec* b : stageBuffers(stage))
    if (bufferNeeded(*b, scene, settings))
      words += uint64_t(b->components) * shapeElements(b->shape, scene.grid.resolution, image);
  return 4u * words;
}

void checkStageMemory(const StageContext& ctx, std::string_view stage, double copies) {
  bool image = false;
  for (const BufferSpec* b : stageBuffers(stage)) image |= b->shape == BufferShape::image;
  const Scene& scene = ctx.scene;
  const auto bytes = static_cast<uint64_t>(
      copies * static_cast<double>(stageBufferBytes(stage, scene, ctx.settings)));
  const std::string what =
      image ? std::to_string(scene.camera.width) + "x" + std::to_string(scene.camera.height)
            : std::to_string(scene.grid.resolution) + "^3";
  requireMemory(bytes, "the " + std::string(stage) + " buffers at " + what, scene.file,
                image ? "camera.resolution" : "grid.resolution");
}

}  // namespace voxgi
