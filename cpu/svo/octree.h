// The CPU build of the sparse voxel octree (shaders/shared/svo/svo_layout.h) in its canonical
// form: tiles allocated level by level in Morton order of their keys, so the structure depends on
// the set of samples alone, never on their order or on threads. The GPU allocates with atomics
// in whatever order its threads run; the diff compares both in this form, per key.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "common/buffer.h"
#include "shaders/shared/svo/splat_kernel.h"

namespace voxgi::cpu::svo {

struct Octree {
  int depth = 0;
  Words nodes;      // kNodeWords per node, 8 nodes a node tile (levels 1 .. depth-1)
  Words tiles;      // kTileWords per node tile; tile 0 is the root tile
  Words leafTiles;  // kTileWords per leaf tile (level depth)
  // First node tile of each level: levelStart[l] for l = 1 .. depth-1, levelStart[depth] = the
  // node tile count (index 0 unused).
  std::vector<uint32_t> levelStart;
  std::vector<std::vector<uint32_t>> levelKeys;  // each level's tile keys, sorted (index 1..depth)

  size_t tileCount() const { return tiles.size() / 4; }
  size_t leafTileCount() const { return leafTiles.size() / 4; }
  // The node tile of `level` (< depth) or leaf tile (level == depth) keyed `key`; kSvoNull if
  // none. Binary search in the level's sorted keys.
  uint32_t findTile(int level, uint32_t key) const;
};

// The tree of depth `depth` over the leaves the samples' RoIs touch, with every ancestor, the
// border tiles the brick boundaries need (docs/svo.md) and the neighbour pointers. Samples outside
// the leaf domain [0, 2^depth)^3 add nothing.
Octree buildOctree(std::span<const shared::SvoSample> samples, int depth);

// The fixed-point sums the samples add to the leaves (kSumWords per leaf voxel, 8 per leaf tile
// in local-id order), in units of 1/scale. Throws InputError naming `source` when a leaf's
// opacity sum would pass 2^31 - 1 units.
Words accumulateLeaves(const Octree& octree, std::span<const shared::SvoSample> samples,
                       float scale, const std::string& source);

// Bricks of the tiles of `level` (leaf tiles for level == depth): from `interior`, `components`
// words per voxel, 8 voxels a tile in local-id order, to 27 texels a tile with the positive
// boundary copied from the neighbouring tiles' interiors (0 where there is none), found through
// the parent level's neighbour pointers.
Words completeBricks(const Octree& octree, int level, const Words& interior, int components);

}  // namespace voxgi::cpu::svo
