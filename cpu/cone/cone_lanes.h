// The CPU's fast path for shared::marchCone: a stream of cones marched several at a time, one per
// SIMD lane (xsimd: two batches of 4 lanes on SSE2, 8 on AVX2, 16 on AVX-512, the widest this CPU
// runs, cpu/simd.h). A lane whose cone ends takes the next cone of the stream, so lanes
// stay busy while neighbouring cones end at different steps. The per-step arithmetic (position,
// width, level, opacity correction, compositing) runs in the lanes; each lane's sample is filtered
// on its own, a voxel's four words in one register (on AVX-512, the three faces a directional
// level's sample reads in one register, blended together). It computes exactly what marchCone
// computes: the same operations in the same order, no fused multiply-add
// (tests/cone/cone_lanes_test.cpp checks it bit for bit), so the CPU's images do not depend on
// which path traced them.
#pragma once

#include <span>

#include "cpu/simd.h"
#include "cpu/cone/cone_volumes.h"

namespace voxgi::cpu {

// One cone: marchCone's arguments but the kind, which all cones of a stream share.
struct ConeJob {
  glm::vec3 origin;
  glm::vec3 direction;  // unit
  float rise;           // direction . n of the surface it leaves
  float tanHalf;        // tan(half aperture)
  float maxDistance;    // voxels
};

// hits[i] = shared::marchCone(volumes, jobs[i]..., kind, params), bit for bit, on the lanes of
// simdLevel().
void marchCones(const ConeVolumes& volumes, std::span<const ConeJob> jobs, int kind,
                const shared::ConeTraceParams& params, std::span<shared::ConeHit> hits);
// The same on the lanes of `level`, which this CPU must run (tests compare the levels).
void marchCones(SimdLevel level, const ConeVolumes& volumes, std::span<const ConeJob> jobs,
                int kind, const shared::ConeTraceParams& params, std::span<shared::ConeHit> hits);

// Each instruction set's march (cone_lanes_impl.h), for the dispatch above. They read the volumes
// as plain pointers, so that the code built for AVX2 or AVX-512 calls no inline function another
// unit shares (an out-of-line copy of one could be the one the whole program links).
namespace cone_lanes {
// The sparse voxel octree's levels as bricks (cpu/svo/svo_volumes.h, TreeBricks) in place of dense
// levels: pyramid level l's trilinear cell is read from the 3^3 brick of the tile that holds its
// lowest corner, as SvoVolumes::filterBrickCell reads it.
struct TreeBricks {
  const uint32_t* levels[16];  // per pyramid level: a tile's 27 texels of faces[l] x 4 words each
  uint32_t firstTile[16];      // the level's first tile number (its bricks start there)
  int faces[16];               // 1 (the leaves) or 6 (a node level's faces)
  // The tile number at pyramid level `level`, tile coordinate (x, y, z); shared::kSvoNull where
  // there is none. Called only when a lane's last tile at that level was another.
  uint32_t (*findTile)(const void* tree, int level, uint32_t x, uint32_t y, uint32_t z);
  const void* tree;
};
struct Volumes {
  const uint32_t* levels[16];    // ConeVolumes::levels
  const uint64_t* occupied[16];  // each level's CellOccupancy::bits()
  size_t occupiedSide[16];       // and CellOccupancy::side()
  int faces;
  int n;
  const TreeBricks* bricks = nullptr;  // set: the octree's bricks, not the dense levels above
};
void marchConesSse2(const Volumes& volumes, std::span<const ConeJob> jobs, int kind,
                    const shared::ConeTraceParams& params, std::span<shared::ConeHit> hits);
void marchConesAvx2(const Volumes& volumes, std::span<const ConeJob> jobs, int kind,
                    const shared::ConeTraceParams& params, std::span<shared::ConeHit> hits);
void marchConesAvx512(const Volumes& volumes, std::span<const ConeJob> jobs, int kind,
                      const shared::ConeTraceParams& params, std::span<shared::ConeHit> hits);
}  // namespace cone_lanes

// What the lanes read of a dense pyramid.
cone_lanes::Volumes laneVolumes(const ConeVolumes& volumes);

// marchCones over `volumes` as they are (a dense pyramid or the octree's bricks) on the lanes of
// `level`.
void marchCones(SimdLevel level, const cone_lanes::Volumes& volumes, std::span<const ConeJob> jobs,
                int kind, const shared::ConeTraceParams& params, std::span<shared::ConeHit> hits);

}  // namespace voxgi::cpu
