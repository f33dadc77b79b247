#include "common/stage.h"

#include "common/error.h"
#include "common/memory.h"

namespace voxgi {

VoxelizeMode parseVoxelizeMode(const std::string& text) {
  if (text == "conservative") return VoxelizeMode::conservative;
  if (text == "antialiased") return VoxelizeMode::antialiased;
  throw InputError("--mode", "", "must be conservative or antialiased, got '" + text + "'");
}

const char* voxelizeModeName(VoxelizeMode mode) {
  return mode == VoxelizeMode::conservative ? "conservative" : "antialiased";
}

void checkStageMemory(const Scene& scene, std::string_view stage, double copies) {
  const int n = scene.grid.resolution;
  const auto bytes = static_cast<uint64_t>(
      copies * static_cast<double>(stageBufferBytes(stage, glm::ivec3(n), scene.hasEmission())));
  requireMemory(bytes, "the " + std::string(stage) + " buffers at " + std::to_string(n) + "^3",
                scene.file, "grid.resolution");
}

}  // namespace voxgi
