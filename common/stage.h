// What a stage runs on: the scene, the settings, and inputs prepared once for both backends.
#pragma once

#include <string>

#include "common/buffer.h"
#include "common/effect_plan.h"
#include "common/scene.h"
#include "common/settings.h"
#include "common/voxel_triangles.h"

namespace voxgi {

struct StageContext {
  StageContext(const Scene& s, const Settings& st, const VoxelTriangles& t)
      : scene(s), settings(st), triangles(t), plan(planEffects(s, st)) {}
  const Scene& scene;
  const Settings& settings;
  const VoxelTriangles& triangles;  // prepareVoxelTriangles(scene, scene.grid)
  const EffectPlan plan;            // planEffects(scene, settings)
};

// Whether the plan produces the buffer: its stage runs and the buffer's need holds.
bool bufferNeeded(const BufferSpec& spec, const EffectPlan& plan);
// Bytes of the buffers `stage` produces.
uint64_t stageBufferBytes(std::string_view stage, const Scene& scene, const EffectPlan& plan);

// Checks the grid and memory before a stage allocates its buffers; throws InputError naming the
// scene's grid.resolution (or camera.resolution for image stages).
void checkStageMemory(const StageContext& ctx, std::string_view stage, double copies = 1.0);

}  // namespace voxgi
