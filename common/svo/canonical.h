// The canonical form of a sparse voxel octree's words (docs/svo.md): node tiles ordered by level
// and then key, leaf tiles by key, and every reference (children, neighbours, parents, the leaf
// sums' blocks) renumbered to match. The CPU build allocates in this order; the GPU's atomics
// allocate in any order, and its octree is put in this form before anything compares it.
#pragma once

#include "common/buffer.h"

namespace voxgi::svo {

struct OctreeWords {
  Words nodes;      // kNodeWords per node, 8 a node tile
  Words tiles;      // kTileWords per node tile
  Words leafTiles;  // kTileWords per leaf tile
  Words sums;       // kSumWords per leaf, 8 a leaf tile (may be empty)
};

// Reorders `octree` (of tree depth `depth`) into the canonical form.
void canonicalize(OctreeWords& octree, int depth);

}  // namespace voxgi::svo
