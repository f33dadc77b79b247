// Checking buffers made outside voxgi against the CPU oracle: another engine's voxel cone tracer,
// or dumps written elsewhere (`voxgi diff --against`, `voxgi.check` in Python). The candidate
// buffers take the place of a second backend's in the registered comparison of each
// (validation/comparisons.inc: metric, tolerance, tie rule, the octree's canonical order), so the
// report is the one `voxgi diff` gives.
#pragma once

#include "common/buffer.h"
#include "common/pipeline.h"
#include "validation/diff.h"

namespace voxgi::validation {

// The stage every buffer of `candidate` belongs to; throws InputError naming `source` when the set
// is empty or its buffers come from different stages.
const StageSpec& candidateStage(const BufferSet& candidate, const std::string& source);

// Throws InputError naming `stage` when ctx's plan skips it: there is no oracle to check against.
void requireOracle(const StageContext& ctx, const StageSpec& stage);

// Compares each buffer of `candidate` (all of one stage) with the oracle's, `oracle` holding the
// oracle's outputs of that stage and those before it (runPipeline up to it). The report lists the
// candidate's buffers only; one the plan does not produce fails as `voxgi diff` fails it, and one
// whose extent differs from the oracle's fails with both extents.
StageReport checkStage(const StageContext& ctx, const BufferSet& oracle,
                       const BufferSet& candidate);

}  // namespace voxgi::validation
