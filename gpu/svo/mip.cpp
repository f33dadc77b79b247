// GPU mip stage: the last frame's radiance up the tree (gpu/svo/mip.h, mipTree).
#include "gpu/svo/mip.h"

#include "common/svo/stage_inputs.h"
#include "common/svo/tree_depth.h"
#include "gpu/stages.h"
#include "shaders/shared/svo/svo_layout.h"

namespace voxgi::gpu::svo {
namespace {

using voxgi::svo::LeafRadiance;
using voxgi::svo::NodeLevels;

// Node tiles per level: tiles [start[l], start[l + 1]) are level l's (the canonical order).
std::vector<uint32_t> levelStarts(const Tree& t) {
  std::vector<uint32_t> start(size_t(t.depth) + 1, 0);
  const size_t tiles = t.words.tiles.size() / shared::kTileWords;
  uint32_t s = 0;
  for (int l = 1; l <= t.depth; ++l) {
    while (s < tiles && t.words.tiles[s * shared::kTileWords + shared::kTileLevel] < uint32_t(l))
      ++s;
    start[size_t(l)] = s;
  }
  return start;
}

}  // namespace

// Fills v.nodeFaces from `first`'s leaves up to the root tile; returns them per level.
NodeLevels mipInto(const Gl& gl, const Tree& t, const SvoVolumes& v, voxgi::svo::FirstStep first) {
  Program program(gl, {&shaders::svo_mip_comp});
  program.use();
  program.set("uDepth", t.depth);
  program.set("uNdfWeights", first == voxgi::svo::FirstStep::ndf ? 1 : 0);
  v.bind(gl);
  const std::vector<uint32_t> start = levelStarts(t);
  NodeLevels out;
  out.levels.resize(size_t(t.depth));
  for (int level = t.depth - 1; level >= 1; --level) {
    const uint32_t tiles = start[size_t(level) + 1] - start[size_t(level)];
    program.set("uLevel", level);
    program.set("uFirst", start[size_t(level)] * 8u);
    program.set("uCount", tiles * 8u);
    dispatchLinear(gl, size_t(tiles) * 8);
    out.levels[size_t(level)] = downloadHalves(gl, v.nodeFaces.get(), size_t(tiles) * 8 * 6,
                                               size_t(start[size_t(level)]) * 8 * 6);
  }
  gl.check("mip");
  return out;
}

NodeLevels mipTree(GlContext& context, const Tree& tree, const voxgi::svo::Leaves& leaves,
                   const LeafRadiance& radiance, voxgi::svo::FirstStep first) {
  context.makeCurrent();
  const SvoVolumes v(context.gl(), tree, leaves, &radiance);
  return mipInto(context.gl(), tree, v, first);
}

}  // namespace voxgi::gpu::svo

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
