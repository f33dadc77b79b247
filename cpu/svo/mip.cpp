// CPU mip stage: the last frame's leaf radiance up the tree (cpu/svo/leaf_light.h, mipTree).
#include "common/svo/stage_inputs.h"
#include "common/svo/tree_depth.h"
#include "cpu/stages.h"
#include "cpu/svo/leaf_light.h"

namespace voxgi::cpu {

void svo::mip(const StageContext& ctx, BufferSet& buffers) {
  using namespace voxgi::svo;
  const int depth = treeDepth(ctx.scene);
  const Octree o = octreeFromWords(treeWords(buffers), depth);
  const Leaves leaves = treeLeaves(buffers);
  const FirstStep first = firstStep(ctx.settings);
  const LeafRadiance radiance = vec4Values(buffers.at(BufferId::svo_propagate_radiance));
  buffers.put(nodeFacesBuffer(mipTree(o, leaves, radiance, first)));
}

}  // namespace voxgi::cpu
