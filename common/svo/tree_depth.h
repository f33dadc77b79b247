// The octree's depth: its leaves are the scene grid's voxels, so depth = log2 grid.resolution.
#pragma once

#include "common/scene.h"

namespace voxgi::svo {

// Deepest tree: leaf keys are 32-bit Morton codes (3 bits a level).
constexpr int kMaxDepth = 10;
// Shallowest: the root tile (level 1) and a level of leaf tiles below it.
constexpr int kMinDepth = 2;

// log2 of the scene's grid resolution; throws InputError naming the scene's grid.resolution when
// the tree would be shallower than kMinDepth or deeper than kMaxDepth.
int treeDepth(const Scene& scene);

}  // namespace voxgi::svo
