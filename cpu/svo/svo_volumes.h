// The sparse voxel octree as the cone library's kernels read it on the CPU (docs/svo.md): the
// leaves' resolved attributes, their light and the node levels' faces, found by walking the tree
// (SvoVolumes, the twin of shaders/svo/svo_volumes.glsl), every level as bricks for the cones'
// trilinear cells, and the loops over the real leaves. Every value the light's pools hold (the
// direct light, a frame's radiance and gathered light, the node faces) is rounded to halves as
// the GPU's pools store it (shaders/shared/half_float.h; common/svo/stages.inc).
#pragma once

#include <bit>
#include <vector>

#include <tbb/blocked_range.h>

#include "common/parallel.h"
#include "common/svo/light_types.h"
#include "cpu/svo/bricks.h"
#include "cpu/cone/cone_lanes.h"
#include "shaders/shared/cone/cone_types.h"
#include "shaders/shared/cone/voxel_light.h"
#include "shaders/shared/svo/svo_sample.h"

namespace voxgi::cpu::svo {

using voxgi::svo::FirstStep;
using voxgi::svo::FrameOutputs;
using voxgi::svo::LeafRadiance;
using voxgi::svo::Leaves;
using voxgi::svo::NodeLevels;

// Every level's values as bricks (completeBricks) for the gather's trilinear cells, indexed by
// tree level: the leaves' radiance (one RGBA a texel) and each node level's six faces (six a
// texel).
struct TreeBricks {
  std::vector<std::vector<glm::vec4>> levels;
};
TreeBricks treeBricks(const Octree& octree, const LeafRadiance& radiance, const NodeLevels& mips);

struct SvoVolumes;
// The bricks as the cone lanes read them (cone_lanes.h), their tiles found through `tree`'s node
// words; both must outlive the result.
cone_lanes::TreeBricks treeLaneBricks(const SvoVolumes& tree, const TreeBricks& bricks);

// What the shared kernels read: the leaves (pyramid level 0) and node levels (pyramid level m is
// tree level depth - m), found by walking the tree (svo_layout.h) with the last tile remembered.
// One per task: the memo is not shared.
struct SvoVolumes {
  const Octree& octree;
  const Leaves& leaves;
  const LeafRadiance* radiance = nullptr;  // pyramid level 0
  const NodeLevels* nodes = nullptr;       // pyramid levels 1 ..
  const LeafRadiance* direct = nullptr;    // the bounce's directAt
  const std::vector<shared::LightData>* lights = nullptr;
  const std::vector<shared::ConeData>* cones = nullptr;
  const Words* leafBricks = nullptr;   // svoBrickAt's leaf bricks, 4 floats a texel
  const TreeBricks* bricks = nullptr;  // filterBrickCell's; without them the kernel reads taps
  // Bit mortonEncode(v) set where leaf v's opacity is above 0 (opaqueLeaves): opacityAt answers 0
  // for the others without finding their tile, which is where the visibility rays spend most of
  // their steps.
  const std::vector<uint32_t>* opaque = nullptr;
  mutable int memoLevel = -1;
  mutable glm::uvec3 memoTile{0};
  mutable uint32_t memoIndex = shared::kSvoNull;

  uint svoNodeWord(uint i) const { return octree.nodes[i]; }
  // The tile of tree `level` at tile coordinate `tile` (svoFindTile), remembered for the next call.
  uint32_t tileAt(int level, glm::uvec3 tile) const;
  // The value index (tile slot x 8 + local id) of voxel v of tree level `level`; -1 if its tile
  // does not exist.
  int64_t slot(int level, glm::ivec3 v) const;
  // Inline for the visibility rays' steps, most of which the opaque bits answer.
  float opacityAt(glm::ivec3 v) const {
    if (opaque != nullptr) {
      const uint32_t key = shared::mortonEncode(glm::uvec3(v));
      if (((*opaque)[key >> 5] >> (key & 31u) & 1u) == 0) return 0.0f;
    }
    return leafOpacity(v);
  }
  // The leaf's clamped opacity, found through its tile.
  float leafOpacity(glm::ivec3 v) const;
  glm::vec3 albedoAt(glm::ivec3 v) const;
  glm::vec3 normalAt(glm::ivec3 v) const;
  glm::vec3 emissionAt(glm::ivec3 v) const;
  glm::vec4 directAt(glm::ivec3 v) const;
  glm::vec4 pyramidAt(int level, int face, glm::ivec3 v) const;
  bool cellEmpty(int, glm::ivec3) const { return false; }
  // shared::filterCell of pyramid `level` from the cell's tile brick when `bricks` are set: one
  // tile lookup and eight texels, the same values in the same order as the kernel's eight
  // pyramidAt taps ([Salm 2015, §4.4]'s sampling; the border tiles make a missing tile's cell 0).
  // False without bricks.
  bool filterBrickCell(int level, int face, const shared::TrilinearCell& c, glm::vec4& out) const;
  shared::LightData lightAt(int i) const { return (*lights)[size_t(i)]; }
  shared::ConeData coneAt(int i) const { return (*cones)[size_t(i)]; }
  glm::vec4 svoBrickAt(int, int, uint tile, uint texel) const {
    const uint32_t* w = leafBricks->data() + (size_t(tile) * shared::kBrickTexels + texel) * 4;
    return {std::bit_cast<float>(w[0]), std::bit_cast<float>(w[1]), std::bit_cast<float>(w[2]),
            std::bit_cast<float>(w[3])};
  }
};

// Calls f(leaf slot, leaf coordinate) for every leaf of the leaf tiles in `tiles` that holds
// samples, in slot order.
template <class F>
void forEachRealLeaf(const Octree& octree, const tbb::blocked_range<size_t>& tiles, const F& f) {
  for (size_t t = tiles.begin(); t != tiles.end(); ++t) {
    const uint32_t key = octree.leafTiles[t * shared::kTileWords + shared::kTileKey];
    const uint32_t parent = octree.leafTiles[t * shared::kTileWords + shared::kTileParent];
    const uint32_t mask = (octree.nodes[size_t(parent) * shared::kNodeWords + shared::kNodeFlags] >>
                           shared::kNodeChildShift) &
                          255u;
    for (uint32_t local = 0; local < 8; ++local)
      if ((mask >> local) & 1u)
        f(t * 8 + local, glm::ivec3(shared::mortonDecode((key << 3) | local)));
  }
}

// The same for every leaf tile, in parallel over tiles.
template <class F>
void forEachRealLeaf(const Octree& octree, const F& f) {
  parallelFor(size_t(0), octree.leafTileCount(),
              [&](size_t t) { forEachRealLeaf(octree, tbb::blocked_range<size_t>(t, t + 1), f); });
}

// SvoVolumes::opaque for `octree`'s leaves, or empty above depth 9 (a bit per possible leaf:
// 16 MiB at depth 9).
std::vector<uint32_t> opaqueLeaves(const Octree& octree, const Leaves& leaves);

}  // namespace voxgi::cpu::svo
