// GPU build stage: the scene's samples (common/svo/samples.h, prepared on the host as for the
// CPU) built with atomics (gpu/svo/octree.h), read back in the canonical form.
#include "common/svo/samples.h"
#include "common/svo/stage_inputs.h"
#include "common/svo/tree_depth.h"
#include "gpu/stages.h"
#include "gpu/svo/octree.h"
#include "gpu/volumes.h"

namespace voxgi::gpu {

void svo::build(GlContext& context, const StageContext& ctx, BufferSet& buffers) {
  beginStage(context, ctx, StageId::svo_build);
  const int depth = voxgi::svo::treeDepth(ctx.scene);
  const SvoSettings& s = ctx.settings.svo;
  const voxgi::svo::SampleSet set = voxgi::svo::prepareSamples(
      ctx.scene, depth, s.meshDensity, uint64_t(s.seed), ctx.settings.vct.emitters);
  voxgi::svo::putTree(buffers,
                      buildOctree(context, set.samples, depth, set.weightScale, ctx.scene.file),
                      set.weightScale, set.emissionScale, ctx.plan.on(Effect::leaf_sums));
}

}  // namespace voxgi::gpu
