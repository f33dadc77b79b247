// CPU build stage: the scene's samples (common/svo/samples.h) into the canonical octree and
// its fixed-point leaf sums (cpu/svo/octree.h), decoded into the leaves.
#include "common/svo/samples.h"
#include "common/svo/stage_inputs.h"
#include "common/svo/tree_depth.h"
#include "cpu/stages.h"
#include "cpu/svo/octree.h"

namespace voxgi::cpu {

void svo::build(const StageContext& ctx, BufferSet& buffers) {
  const int depth = voxgi::svo::treeDepth(ctx.scene);
  const SvoSettings& s = ctx.settings.svo;
  const voxgi::svo::SampleSet set = voxgi::svo::prepareSamples(
      ctx.scene, depth, s.meshDensity, uint64_t(s.seed), ctx.settings.vct.emitters);
  SampleHomes homes;
  Octree o = buildOctree(set.samples, depth, ctx.scene.file, &homes);
  Words sums = accumulateLeaves(o, set.samples, set.weightScale, ctx.scene.file, &homes);
  voxgi::svo::putTree(
      buffers, {std::move(o.nodes), std::move(o.tiles), std::move(o.leafTiles), std::move(sums)},
      set.weightScale, set.emissionScale, ctx.plan.on(Effect::leaf_sums));
}

}  // namespace voxgi::cpu
