// What a stage runs on: its technique, the scene, the settings, the plan, and inputs prepared once
// for both backends.
#pragma once

#include <string>

#include "common/buffer.h"
#include "common/effect_plan.h"
#include "common/scene.h"
#include "common/settings.h"
#include "common/technique.h"
#include "common/voxel_triangles.h"

namespace voxgi {

struct StageContext {
  StageContext(const Technique& t, const Scene& s, const Settings& st, const VoxelTriangles& tr)
      : technique(t), scene(s), settings(st), triangles(tr), plan(t.plan(s, st)) {}
  const Technique& technique;
  const Scene& scene;
  const Settings& settings;
  const VoxelTriangles& triangles;  // prepareVoxelTriangles(scene, scene.grid)
  const EffectPlan plan;            // technique.plan(scene, settings)
};

// Bytes of the buffers `stage` produces under the plan.
uint64_t stageBufferBytes(StageId stage, const Scene& scene, const EffectPlan& plan);

// What a stage writes under a dark plan (EffectPlan::dark), on either backend: its planned
// buffers, every word zero (the black image and its light terms). Only the technique's last stage
// runs in such a plan.
void putDarkOutputs(const StageContext& ctx, StageId stage, BufferSet& buffers);

// Checks the grid and memory before a stage allocates its buffers; throws InputError naming the
// scene's grid.resolution (or camera.resolution for image stages).
void checkStageMemory(const StageContext& ctx, StageId stage, double copies = 1.0);

}  // namespace voxgi
