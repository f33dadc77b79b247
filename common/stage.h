// What a stage runs on: the scene, the settings, and inputs prepared once for both backends.
#pragma once

#include <string>

#include "common/buffer.h"
#include "common/scene.h"
#include "common/settings.h"
#include "common/voxel_triangles.h"

namespace voxgi {

struct StageContext {
  const Scene& scene;
  const Settings& settings;
  const VoxelTriangles& triangles;  // prepareVoxelTriangles(scene, scene.grid)
};

// Whether a stage run with `settings` on `scene` produces the buffer.
bool bufferNeeded(const BufferSpec& spec, const Scene& scene, const Settings& settings);
// Bytes of the buffers `stage` produces.
uint64_t stageBufferBytes(std::string_view stage, const Scene& scene, const Settings& settings);

// Checks the grid and memory before a stage allocates its buffers; throws InputError naming the
// scene's grid.resolution (or camera.resolution for image stages).
void checkStageMemory(const StageContext& ctx, std::string_view stage, double copies = 1.0);

}  // namespace voxgi
