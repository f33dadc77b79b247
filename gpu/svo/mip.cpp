// GPU mip stage: the last frame's radiance up the tree (gpu/svo/leaf_light.h, mipTree).
#include "common/svo/stage_inputs.h"
#include "common/svo/tree_depth.h"
#include "gpu/stages.h"
#include "gpu/svo/leaf_light.h"

namespace voxgi::gpu {

void svo::mip(GlContext& context, const StageContext& ctx, BufferSet& buffers) {
  using namespace voxgi::svo;
  beginStage(context, ctx, StageId::svo_mip);
  const int depth = treeDepth(ctx.scene);
  const OctreeWords words = treeWords(buffers);
  const Tree tree{words, depth};
  const Leaves leaves = treeLeaves(buffers);
  const FirstStep first = firstStep(ctx.settings);
  const LeafRadiance radiance = vec4Values(buffers.at(BufferId::svo_propagate_radiance));
  buffers.put(nodeFacesBuffer(mipTree(context, tree, leaves, radiance, first)));
}

}  // namespace voxgi::gpu
