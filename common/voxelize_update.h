// The voxelize stage's partial update in a sequence ([Villegas 2017, §1.2] revoxelizes only its
// dynamic objects): when few meshes moved since the frame before, both backends start from that
// frame's integer sums, take the moved meshes' contributions of that frame out (adding 0 - v
// modulo 2^32 is exact), add this frame's, and resolve; the buffers are the ones voxelizing every
// triangle gives, bit for bit.
#pragma once

#include <optional>
#include <utility>
#include <vector>

#include "common/stage.h"

namespace voxgi {

// Triangle ranges [first, end) of the meshes that moved since the frame before, in that frame's
// triangles and in this one's.
struct MovedTriangles {
  std::vector<std::pair<size_t, size_t>> before, now;
};

// What moved since the frame before (ctx.previous), when its voxelize buffers can be updated in
// part: the same grid, meshes and emission scale, every buffer the stage wrote then in the stash
// (the emission ones exactly when `emissive`), and the moved meshes' triangles of both frames
// together fewer than this frame's (else rebuilding costs no more). nullopt otherwise.
std::optional<MovedTriangles> movedTriangles(const StageContext& ctx, bool emissive);

// The box, in voxel coordinates, outside which voxelize's buffers are the frame before's
// (ctx.previous) whether it rebuilt or updated them: the moved meshes' triangles of both frames,
// grown by a voxel (a voxel's buffers depend only on the triangles that overlap it). nullopt when
// no mesh moved or the frames cannot be compared mesh by mesh (another grid, other meshes).
struct VoxelBox {
  glm::vec3 low, high;
};
std::optional<VoxelBox> changedVoxelBox(const StageContext& ctx);

// The triangles of `ranges`, in order.
std::vector<shared::VoxelTriangle> trianglesIn(
    const VoxelTriangles& triangles, const std::vector<std::pair<size_t, size_t>>& ranges);

}  // namespace voxgi
