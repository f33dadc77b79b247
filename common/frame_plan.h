// The planner in time (docs/motion.md): in a sequence, which of a frame's planned stages run and
// which keep the buffers the previous frame left, from what moved between the two scenes. A stage
// runs when a part of the scene it reads changed (stageSceneInputs) or when a stage before it in
// the plan ran and it reads buffers (stageReadsBuffers); otherwise its buffers are the previous
// frame's, which is what running it would give, since every stage is a deterministic function of
// the scene, the settings and the buffers before it (the incremental-equals-scratch tests hold the
// runner to this).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "common/pipeline.h"

namespace voxgi {

// The parts of the scene a stage reads, from its declaration: its stage_reads bits among geometry,
// lights and camera (the parts that can change from frame to frame; materials, textures, the grid
// and the settings stay fixed through a sequence).
unsigned stageSceneInputs(StageId stage);

// Whether `stage` reads buffers of the stages before it (gbuffer, voxelize and the octree's build
// read the scene alone), from its declaration: one that does not, runs only when what it reads of
// the scene changed.
bool stageReadsBuffers(StageId stage);

// Whether `stage` carries a state of its own from frame to frame (FrameHistory): it declares the
// history among what it reads, ctx's plan says it carries under these settings, and a runner keeps
// the history. Such a stage runs in a frame where nothing it reads changed, until its state
// settles.
bool stageCarries(const StageContext& ctx, StageId stage);

// What moved from one frame's scene to the next's: a set of stage_reads bits (geometry, lights,
// camera) and, for messages, what it was ("the camera moved", "1 mesh moved: 120 of 4,000 triangles
// (3 %)").
struct SceneChange {
  unsigned parts = 0;
  std::vector<std::string> what;
  std::string describe() const;  // the `what`s joined; "nothing moved" when there are none
};
SceneChange sceneChange(const Scene& before, const Scene& after);

// One planned stage of a frame: whether it runs, and why (or why its buffers are reused).
struct FrameStep {
  const StageSpec* stage;
  bool runs;
  std::string why;
};

// The volume stages of a frame under update.interval: those before the first planned stage that
// reads the camera. `due`: the frame brings them up to date, from what changed since they last
// were (`change`); otherwise they keep their buffers and update `framesLeft` frames later.
struct VolumeUpdate {
  bool due = true;
  SceneChange change;
  int framesLeft = 0;
};

// The steps of a frame: every planned stage runs in the first frame (`previous` null) and when
// the plan's decisions changed (EffectPlan::sameDecisions); otherwise as the header says, the
// volume stages following `volumes` where it is given.
std::vector<FrameStep> frameSteps(const StageContext& ctx, const EffectPlan* previous,
                                  const SceneChange& change, const VolumeUpdate* volumes = nullptr);

// Runs the steps that run on `backend`, in order; a reused stage's buffers stay in `buffers` as
// the previous frame left them. Throws std::logic_error when a stage that runs does not write
// exactly its planned buffers, or a reused one's are missing.
void runFrame(StageBackend& backend, const StageContext& ctx, BufferSet& buffers,
              const std::vector<FrameStep>& steps, const StageObserver& observe = {});

// The frames of a sequence on one backend: each frame's scene and settings in, the stages
// frameSteps says run (all of them when `scratch`), the others keeping the buffers the frame
// before left, and every stage given the state stages carry (StageContext::history); a stage that
// reruns gets the frame before (StageContext::previous) when the plan decided the same. Under
// update.interval=N > 1 the volume stages run on every N-th frame (and on any whose plan decided
// otherwise) and their previous frame is the last one they ran on.
class FrameRunner {
 public:
  FrameRunner(const Technique& technique, StageBackend& backend, bool scratch = false);
  // Runs the frame; returns its steps. Throws as runFrame does, and InputError from the stages.
  const std::vector<FrameStep>& run(Scene scene, const Settings& settings,
                                    const StageObserver& observe = {});
  const Scene& scene() const { return scene_; }
  const Settings& settings() const { return settings_; }
  const VoxelTriangles& triangles() const { return triangles_; }
  const BufferSet& buffers() const { return buffers_; }
  const std::vector<FrameStep>& steps() const { return steps_; }
  // What moved since the frame before; "the first frame" or "from scratch" where nothing is
  // compared.
  std::string why() const;

 private:
  const Technique& technique_;
  StageBackend& backend_;
  bool scratch_;
  bool first_ = true;
  Scene scene_, previousScene_;
  Settings settings_;
  VoxelTriangles triangles_, previousTriangles_;
  BufferSet buffers_;
  std::optional<EffectPlan> plan_;
  SceneChange change_;
  // Under update.interval > 1: the scene and triangles the volume stages last ran on, and the
  // frames run since.
  std::optional<Scene> volumeScene_;
  VoxelTriangles volumeTriangles_;
  int framesSinceUpdate_ = 0;
  // What the stages carry from frame to frame, kept from scratch too.
  FrameHistory history_;
  std::vector<FrameStep> steps_;
};

}  // namespace voxgi
