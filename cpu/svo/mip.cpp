// CPU mip stage: the last frame's leaf radiance up the tree (cpu/svo/mip.h, mipTree).
#include "cpu/svo/mip.h"

#include "common/parallel.h"
#include "common/svo/stage_inputs.h"
#include "common/svo/tree_depth.h"
#include "cpu/stages.h"
#include "shaders/shared/cone/mip.h"
#include "shaders/shared/half_float.h"
#include "shaders/shared/svo/mip_kernel.h"

namespace voxgi::cpu::svo {
namespace {

using shared::kSvoNull;

// The tiles of a node level in tile order: [first, first + count).
std::pair<size_t, size_t> levelRange(const Octree& o, int level) {
  return {o.levelStart[size_t(level)],
          o.levelStart[size_t(level) + 1] - o.levelStart[size_t(level)]};
}

// The 8 children of one node for the shared mip kernel: leaves (one value, optionally weighted
// per face by its normal) or a node level's six faces.
struct Children {
  const glm::vec4* values;
  const glm::vec3* normals;  // leaves under FirstStep::ndf, else nullptr
  bool leaves;
  glm::vec4 childAt(int face, glm::ivec3 c) const {
    const int local = c.x + 2 * c.y + 4 * c.z;
    if (!leaves) return values[local * shared::kFaces + face];
    const glm::vec4 v = values[local];
    return normals == nullptr ? v : shared::ndfWeighted(v, normals[local], face);
  }
};

}  // namespace

NodeLevels mipTree(const Octree& octree, const Leaves& leaves, const LeafRadiance& radiance,
                   FirstStep first) {
  NodeLevels out;
  out.levels.resize(size_t(octree.depth));
  for (int level = octree.depth - 1; level >= 1; --level) {
    const size_t firstTile = levelRange(octree, level).first;
    const size_t count = levelRange(octree, level).second;
    std::vector<glm::vec4>& values = out.levels[size_t(level)];
    values.assign(count * 8 * shared::kFaces, glm::vec4(0.0f));
    const bool fromLeaves = level + 1 == octree.depth;
    parallelFor(size_t(0), count, [&](size_t i) {
      for (size_t local = 0; local < 8; ++local) {
        const size_t node = (firstTile + i) * 8 + local;
        const uint32_t child = octree.nodes[node * shared::kNodeWords + shared::kNodeChild];
        if (child == kSvoNull) continue;
        Children c{};
        c.leaves = fromLeaves;
        if (fromLeaves) {
          c.values = &radiance[size_t(child) * 8];
          c.normals = first == FirstStep::ndf ? &leaves.normal[size_t(child) * 8] : nullptr;
        } else {
          const size_t childRank = child - octree.levelStart[size_t(level) + 1];
          c.values = &out.levels[size_t(level) + 1][childRank * 8 * shared::kFaces];
        }
        for (int face = 0; face < shared::kFaces; ++face)
          values[(i * 8 + local) * shared::kFaces + size_t(face)] =
              shared::roundToHalf4(shared::mipAnisotropic(c, glm::ivec3(0), face));
      }
    });
  }
  return out;
}

}  // namespace voxgi::cpu::svo

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
