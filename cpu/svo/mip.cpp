// CPU mip stage: the last frame's leaf radiance up the tree (cpu/svo/leaf_light.h, mipTree)
// and the gathered light's leaf bricks (cpu/svo/octree.h, completeBricks).
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
  const Buffer& gathered = buffers.at(BufferId::svo_propagate_gathered);
  Buffer bricks(BufferId::svo_mip_gathered_bricks,
                glm::ivec3(int(o.leafTileCount()) * shared::kBrickTexels, 1, 1));
  // A brick's texels are copies of the leaves' values, so the packed halves copy as they are.
  bricks.words = completeBricks(o, depth, gathered.words, int(gathered.elementWords()));
  buffers.put(std::move(bricks));
}

}  // namespace voxgi::cpu
