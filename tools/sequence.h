// A sequence's frames through the one stage runner (docs/motion.md) on the backend the options
// pick, for the commands: FrameRunner's frames with what their log lines say.
#pragma once

#include "common/frame_plan.h"
#include "tools/command.h"

namespace voxgi::tools {

class StageSequence {
 public:
  // `scratch`: every frame runs its whole plan, as a single image would.
  StageSequence(const SceneOptions& options, bool scratch);
  // Runs the frame of `scene` (the sequence's scene at the frame's time); the runner then holds
  // the frame's scene, settings and buffers.
  const FrameRunner& frame(Scene scene);
  double seconds() const { return seconds_; }  // of the last frame, triangle setup included
  std::string backendName() const;
  // "ran 3 of 7 stages (the camera moved)", for the frame's log line.
  std::string summary() const;

 private:
  const SceneOptions& options_;
  BackendChoice backend_;
  FrameRunner runner_;
  size_t ran_ = 0;
  double seconds_ = 0.0;
};

}  // namespace voxgi::tools
