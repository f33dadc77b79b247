// The per-buffer diff engine behind `voxgi diff`: both backends run a stage on the same inputs
// (the CPU's outputs of the stages before it), and every declared buffer is compared with its
// registered comparison. Elements outside the tolerance are classified by the stage's tie
// classifier: a tie (documented near-boundary case) is allowed, anything else fails.
#pragma once

#include <functional>
#include <map>
#include <string>
#include <vector>

#include "common/buffer.h"
#include "common/pipeline.h"
#include "gpu/context.h"

namespace voxgi::validation {

struct BufferReport {
  std::string buffer;
  std::string metric;  // Comparison::describe()
  double tolerance = 0.0;
  std::string reason;
  std::string status;  // "compared", why it was not ("not planned: ..."), or what went wrong
  size_t elements = 0;
  size_t differing = 0;   // elements outside the tolerance
  double fraction = 0.0;  // differing / elements
  double maxAbsDiff = 0.0;
  double maxUlp = 0.0;
  size_t ties = 0, nonTies = 0, unclassified = 0;
  long long worstElement = -1;  // element index of the largest difference, -1 if none
  bool pass = true;
};

// How an element outside its tolerance was classified (decided once per element, for every
// buffer of the stage; the dump's classification grid shows the same decision).
enum class ElementClass : uint8_t { tie = 1, not_a_tie = 2 };

struct StageReport {
  std::string stage;  // StageSpec::qualifiedName
  std::vector<BufferReport> buffers;
  std::map<size_t, ElementClass> outside;  // element -> class; unclassified counts as not_a_tie
  double cpuSeconds = 0.0, gpuSeconds = 0.0;
  std::string skipped;  // non-empty: the plan skips the stage (why); nothing was run
  bool pass = true;
};

// Classification of one element that differs: true for a tie. Built per stage from its context.
using TieClassifier = std::function<bool(size_t element)>;

// Compares two buffer sets on `stage`'s declared buffers against the plan: a buffer the plan
// produces must be on both backends and within its comparison; one it does not must be on
// neither. `classify` may be empty (no ties).
StageReport compareStage(const StageSpec& stage, const EffectPlan& plan, const BufferSet& cpu,
                         const BufferSet& gpu, const TieClassifier& classify);

// The tie classifier of `stage`'s comparisons (one rule for all its buffers; empty for none).
// The buffers must outlive it.
TieClassifier stageTies(const StageSpec& stage, const StageContext& ctx, const BufferSet& cpu,
                        const BufferSet& gpu);

// Runs the planned stages of ctx's technique up to the last of `stages` on the CPU, and each of
// `stages` on both backends from the CPU's outputs of the stages before it, and compares them
// (a requested stage the plan skips is reported as such). In a sequence (ctx.history set), both
// backends get the state stages carry as the CPU found it, and ctx.history goes on with the CPU's.
// With a non-empty `dumpDir`, writes <dir>/<stage>_cpu.vdb, _gpu.vdb and _diff.vdb (gpu - cpu per
// buffer, plus a `classification` grid: 0 agree, 1 tie, 2 not a tie).
std::vector<StageReport> diffStages(const StageContext& ctx, StageBackend& cpu, StageBackend& gpu,
                                    const std::vector<const StageSpec*>& stages,
                                    const std::string& dumpDir);

// The voxelize stage's tie classifier (validation/voxelize_ties.cpp).
TieClassifier voxelizeTies(const StageContext& ctx);
// The gbuffer stage's: a pixel whose backends saw different triangles is a tie if, in the CPU
// image, it lies on a triangle edge (a 4-neighbour sees another triangle or the background); where
// either saw a point cloud's disc, if the ray meets a disc at its rim or both surfaces at depths
// the GPU's depth buffer cannot separate (validation/edge_ties.cpp). The buffers must outlive the
// classifier.
TieClassifier gbufferTies(const StageContext& ctx, const BufferSet& cpu, const BufferSet& gpu);
// A stage that renders square maps (BufferShape::maps, lpv's rsm): the same rule within each map,
// from the stage's own `primitive_id` buffer, which such a stage declares (std::logic_error
// otherwise; validation/edge_ties.cpp).
TieClassifier mapTies(const StageSpec& stage, const BufferSet& cpu, const BufferSet& gpu);

}  // namespace voxgi::validation
