#include "tools/sequence.h"

#include <chrono>
#include <iostream>

namespace voxgi::tools {

StageSequence::StageSequence(const SceneOptions& options, bool scratch)
    : options_(options),
      scratch_(scratch),
      run_{{}, {}, chooseBackend(options.backend, gpu::parseGlPlatform(options.gl)), {}, {}, {}, 0.0} {
  if (!run_.backend.note.empty()) std::cerr << "voxgi: " << run_.backend.note << "\n";
}

const StageRun& StageSequence::frame(Scene scene) {
  const Technique& technique = findTechnique(options_.technique);
  first_ = !plan_;
  change_ = first_ ? SceneChange{} : sceneChange(run_.scene, scene);
  const auto start = std::chrono::steady_clock::now();
  // Unmoved geometry keeps its prepared triangles.
  if (first_ || scratch_ || (change_.parts & kSceneGeometry) != 0)
    run_.triangles = prepareVoxelTriangles(scene, scene.grid);
  run_.scene = std::move(scene);
  run_.settings = options_.settings(run_.scene);
  const StageContext ctx{technique, run_.scene, run_.settings, run_.triangles};
  if (scratch_) run_.buffers = BufferSet{};
  steps_ = frameSteps(ctx, scratch_ || first_ ? nullptr : &*plan_, change_);
  if (scratch_)
    for (FrameStep& s : steps_) s.why = "from scratch";
  run_.stages.clear();
  runFrame(run_.backend.stages(), ctx, run_.buffers, steps_,
           [&](const StageSpec& stage, double) { run_.stages.push_back(&stage); });
  plan_ = ctx.plan;
  run_.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run_;
}

std::string StageSequence::summary() const {
  const std::string why = scratch_ ? "from scratch" : first_ ? "the first frame" : change_.describe();
  return "ran " + std::to_string(run_.stages.size()) + " of " + std::to_string(steps_.size()) +
         " stages (" + why + ")";
}

}  // namespace voxgi::tools
