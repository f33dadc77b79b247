// The sparse voxel octree's layout [Salm 2015, §4.3.1], shared by the CPU and GPU stages and the
// diff (docs/svo.md has the figure). Included by C++ and GLSL.
//
// Levels: the root is implicit and not stored; its eight children, the root tile, are level 1,
// and the leaves are level D = log2 grid.resolution, 2^D per axis over the scene's grid cube. Nodes
// come in tiles of eight, the children of one node; a node's local id in its tile is x | y<<1 |
// z<<2 of its coordinates' lowest bits (svo/morton.h). A tile at level l is keyed by its coordinate
// at level l - 1 (its parent node's), as a Morton key.
//
// Two address spaces, as in the thesis: node tiles (levels 1 .. D-1; the root tile is tile 0)
// hold kNodeWords words per node in `nodes`, node n = 8 tile + local id; leaf tiles (level D) are
// implicit: a leaf parent's child word is the index of its leaf tile, and its flags say which
// leaves hold samples. Each tile has a brick: 2x2x2 voxels, one per node, stored as 3x3x3 with
// the positive boundary copied from the neighbouring tiles, so a trilinear sample needs one tile
// (texel (i, j, k) at i + 3 (j + 3 k); svo_sample.h). Leaf bricks are in the leaf pools,
// node-tile bricks in the mipmap pools, by tile index.
#ifndef VOXGI_SVO_LAYOUT_H
#define VOXGI_SVO_LAYOUT_H
#include "../morton.h"

VOXGI_NAMESPACE_BEGIN

const uint kSvoNull = 0xffffffffu;

// A node: its child tile (a node tile, or the leaf tile at level D-1), its six neighbours at the
// same level (node indices of slots whose tiles exist, in the order +x -x +y -y +z -z), and flags.
const int kNodeWords = 8;
const int kNodeChild = 0;
const int kNodeNeighbour = 1;  // + face (0..5 as +x -x +y -y +z -z)
const int kNodeFlags = 7;
const uint kNodeReal = 1u;        // a sample lies in the node's cell (else an empty slot)
const uint kNodeChildShift = 8u;  // bits 8..15: which children are real

// A tile record (`tiles` for node tiles, `leaf_tiles`): its level, key, parent node (kSvoNull for
// the root tile) and flags.
const int kTileWords = 4;
const int kTileLevel = 0;
const int kTileKey = 1;
const int kTileParent = 2;
const int kTileFlags = 3;
const uint kTileBorder = 1u;  // holds no sample: it only completes a neighbour's brick boundary

const int kBrickTexels = 27;

VOXGI_FN uint brickTexel(ivec3 t) {
  return uint(t.x + 3 * (t.y + 3 * t.z));
}

// The tile of `level` at tile coordinate `tile` (node coordinates at level - 1): its index in its
// address space (leaf tiles for level D), or kSvoNull. Walks down from the root tile through
// FETCH(svoNodeWord)(word index).
VOLUME_FN uint svoFindTile(VOLUMES_IN int level, uvec3 tile) {
  uint t = 0u;
  for (int l = 1; l < level; ++l) {
    uvec3 c = tile >> uint(level - 1 - l);
    uint node = t * 8u + localId(c);
    t = FETCH(svoNodeWord)(node * uint(kNodeWords) + uint(kNodeChild));
    if (t == kSvoNull) return kSvoNull;
  }
  return t;
}

VOXGI_NAMESPACE_END
#endif
