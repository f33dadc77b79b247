// A sequence's frames through the one stage runner (docs/motion.md): one backend for the whole
// sequence, and in each frame the stages frameSteps says run, the others keeping the buffers the
// frame before left (or every stage, from scratch, when asked).
#pragma once

#include <optional>
#include <vector>

#include "common/frame_plan.h"
#include "tools/command.h"

namespace voxgi::tools {

class StageSequence {
 public:
  // `scratch`: every frame runs its whole plan, as a single image would.
  StageSequence(const SceneOptions& options, bool scratch);
  // Runs the frame of `scene` (the sequence's scene at the frame's time); the run's scene,
  // buffers, stages and seconds are this frame's.
  const StageRun& frame(Scene scene);
  const std::vector<FrameStep>& steps() const { return steps_; }
  // "ran 3 of 7 stages (the camera moved)", for the frame's log line.
  std::string summary() const;

 private:
  const SceneOptions& options_;
  bool scratch_;
  bool first_ = true;
  StageRun run_;
  std::optional<EffectPlan> plan_;  // the previous frame's
  SceneChange change_;
  std::vector<FrameStep> steps_;
};

}  // namespace voxgi::tools
