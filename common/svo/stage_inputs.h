// What the octree's stages read, prepared the same way for both backends: the tree's words from
// build's buffers, the leaves decoded from their fixed-point sums, the per-leaf and per-node
// values as buffers and back, and the cone parameters of a tree (common/svo/stages.inc).
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "common/stage.h"
#include "common/svo/canonical.h"
#include "common/svo/light_types.h"
#include "common/cone/cone_trace.h"
#include "common/cone/voxel_light.h"

namespace voxgi::svo {

// Puts build's buffers: the tree's words (moved in), the leaves decoded from its sums and the
// sums' scales; the sums themselves only with `keepSums` (the plan's leaf_sums effect), as the
// leaves hold what every later stage reads.
void putTree(BufferSet& buffers, OctreeWords words, float weightScale, float emissionScale,
             bool keepSums);
// build's words (copies): nodes, tiles and leaf tiles.
OctreeWords treeWords(const BufferSet& buffers);

// The leaf sums in floats: sums / weightScale (times emissionScale for the emission), one value
// per leaf slot. Both factors are powers of two, so the decode is exact wherever a sum fits a
// float's 24 bits, and the same on both backends.
Leaves resolveLeaves(const Words& sums, float weightScale, float emissionScale);
// build's leaves buffer from the leaves (every value rounded to the nearest half: the geometry pool
// of [Salm 2015, §4.3.1], whose GPU twin holds two halves a word) and back.
Buffer leavesBuffer(const Leaves& leaves);
Leaves leavesOf(const Buffer& leaves);
// The leaves as build stored them.
Leaves treeLeaves(const BufferSet& buffers);

// A per-leaf (or per-texel) RGBA buffer of halves (the octree's light, common/svo/stages.inc) and
// back; the values are rounded to the nearest half.
Buffer vec4Buffer(BufferId id, const std::vector<glm::vec4>& values);
std::vector<glm::vec4> vec4Values(const Buffer& buffer);
// mip's node_faces (six faces a node, nodes in canonical order) and back, for a tree whose
// node tiles are `tiles` (kTileWords each, level by level).
Buffer nodeFacesBuffer(const NodeLevels& levels);
NodeLevels nodeLevels(const Buffer& faces, const Words& tiles, int depth);

// svo.first_step as the light functions take it.
FirstStep firstStep(const Settings& settings);

// The cone parameters of voxel cone tracing (common/cone/cone_trace.h) for a tree of `depth`:
// the pyramid's top is the root tile's level (depth - 1), and it is six-faced. Shading traces no
// diffuse cones: the leaves hold the diffuse light.
ConeTraceSetup treeConeTrace(const StageContext& ctx, int depth);
ConeTraceSetup treeGather(const StageContext& ctx, int depth);

}  // namespace voxgi::svo
