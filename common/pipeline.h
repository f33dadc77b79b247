// The one stage runner: every command and test that runs stages (render, dump, diff, bench,
// study) goes through it, so they agree on which stages run, in what order, and on what a stage
// must leave behind.
//
// A backend (cpu/backend.h, gpu/backend.h) runs one stage by its id; the pipeline asks the plan
// which of the technique's steps run, runs them in graph order, and checks after each that the
// backend wrote exactly the buffers the plan says the stage produces.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "common/stage.h"

namespace voxgi {

class StageBackend {
 public:
  virtual ~StageBackend() = default;
  virtual std::string name() const = 0;  // "cpu", "gpu: llvmpipe (LLVM 15.0.6, 256 bits)"
  virtual void run(StageId stage, const StageContext& ctx, BufferSet& buffers) = 0;
};

// What a stage wrote against what the plan says it produces.
struct StageOutputs {
  std::vector<const BufferSpec*> missing;    // planned, not written
  std::vector<const BufferSpec*> unplanned;  // written, not planned
  bool ok() const { return missing.empty() && unplanned.empty(); }
  std::string describe(const StageSpec& stage, const std::string& backend) const;
};

// The technique's steps the plan runs, in graph order, up to and including `last` (all when
// null). Throws std::logic_error when the planner does not decide one of the steps (a stage added
// to common/stages.inc but not to its technique's planner).
std::vector<const StageSpec*> plannedStages(const StageContext& ctx,
                                            const StageSpec* last = nullptr);

// Runs one stage on `backend` and compares what it wrote (buffers of that stage, new or
// replaced) with the plan; `buffers` keeps what was written either way.
StageOutputs runStage(StageBackend& backend, const StageSpec& stage, const StageContext& ctx,
                      BufferSet& buffers);

// Called after each stage with the stage and the seconds the backend took.
using StageObserver = std::function<void(const StageSpec&, double seconds)>;

// Runs the planned stages up to `last` (all when null) on `backend`; throws std::logic_error when
// a stage did not write exactly its planned buffers.
void runPipeline(StageBackend& backend, const StageContext& ctx, BufferSet& buffers,
                 const StageSpec* last = nullptr, const StageObserver& observe = {});

// The stage named `text` for `technique`: "vct/trace_cones", or a bare name among its steps
// ("trace_cones", "gbuffer"); throws InputError naming `source`.
const StageSpec& resolveStage(const Technique& technique, const std::string& text,
                              const std::string& source = "--stage");

}  // namespace voxgi
