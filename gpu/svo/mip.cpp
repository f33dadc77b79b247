// GPU mip stage: the last frame's radiance up the tree (gpu/svo/leaf_light.h, mipTree) and the
// gathered light's leaf bricks (shaders/svo/mip_brick.comp).
#include "common/svo/stage_inputs.h"
#include "common/svo/tree_depth.h"
#include "gpu/program.h"
#include "gpu/stages.h"
#include "gpu/svo/leaf_light.h"
#include "gpu/volumes.h"
#include "shaders/shared/svo/svo_layout.h"

namespace voxgi::gpu {

void svo::mip(GlContext& context, const StageContext& ctx, BufferSet& buffers) {
  using namespace voxgi::svo;
  const Gl& gl = beginStage(context, ctx, StageId::svo_mip);
  const int depth = treeDepth(ctx.scene);
  const OctreeWords words = treeWords(buffers);
  const Tree tree{words, depth};
  const Leaves leaves = treeLeaves(buffers);
  const FirstStep first = firstStep(ctx.settings);
  const LeafRadiance radiance = vec4Values(buffers.at(BufferId::svo_propagate_radiance));
  buffers.put(nodeFacesBuffer(mipTree(context, tree, leaves, radiance, first)));

  const Buffer& gathered = buffers.at(BufferId::svo_propagate_gathered);
  const size_t tiles = words.leafTiles.size() / shared::kTileWords;
  const size_t texels = tiles * shared::kBrickTexels;
  GlBuffer nodes(gl, createBuffer(gl, words.nodes.size() * 4, words.nodes.data()));
  GlBuffer leafTiles(gl, createBuffer(gl, words.leafTiles.size() * 4, words.leafTiles.data()));
  GlBuffer interior(gl, uploadWords(gl, gathered));  // halves, as the pools hold them
  GlBuffer bricks(gl, svo::buildBricks(gl, nodes.get(), leafTiles.get(), interior.get(), tiles, 1));
  Buffer out(BufferId::svo_mip_gathered_bricks, glm::ivec3(int(texels), 1, 1));
  readWords(gl, bricks.get(), out);
  buffers.put(std::move(out));
}

}  // namespace voxgi::gpu
