// What a stage runs on: its technique, the scene, the settings, the plan, and inputs prepared once
// for both backends.
#pragma once

#include <map>
#include <set>
#include <string>
#include <vector>

#include "common/buffer.h"
#include "common/effect_plan.h"
#include "common/scene.h"
#include "common/settings.h"
#include "common/technique.h"
#include "common/voxel_triangles.h"

namespace voxgi {

// The frame before in a sequence, for a stage that can update its buffers in part instead of
// rebuilding them (docs/motion.md): the frame's scene and triangles, and the stage's own buffers
// of that frame, which runStage moves here before the stage runs. A stage's output must be the
// same whether or not it uses them.
struct PreviousFrame {
  const Scene* scene = nullptr;
  const VoxelTriangles* triangles = nullptr;
  BufferSet stash;
};

// What stages carry from one frame of a sequence to the next as an input of their own, not a
// cache: a stage run from scratch reads it too, and its output depends on it (the octree's
// progressive bounces, [Salm 2015, §4.4.3]). Each stage packs its own words; `settled` holds the
// stages whose last run left their carried words as it found them, so that running them again on
// unchanged inputs would change nothing (the planner reuses them then).
struct FrameHistory {
  std::map<StageId, std::vector<uint32_t>> carried;
  std::set<StageId> settled;
};

struct StageContext {
  StageContext(const Technique& t, const Scene& s, const Settings& st, const VoxelTriangles& tr)
      : technique(t), scene(s), settings(st), triangles(tr), plan(t.plan(s, st)) {}
  const Technique& technique;
  const Scene& scene;
  const Settings& settings;
  const VoxelTriangles& triangles;  // prepareVoxelTriangles(scene, scene.grid)
  const EffectPlan plan;            // technique.plan(scene, settings)
  // Set by the runner of a sequence when the frame before ran under the same decisions.
  PreviousFrame* previous = nullptr;
  // Set by the runner of a sequence from its first frame on, from scratch too.
  FrameHistory* history = nullptr;
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
