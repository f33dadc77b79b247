#include "common/voxelize_update.h"

namespace voxgi {

namespace {

size_t triangleCount(const std::vector<std::pair<size_t, size_t>>& ranges) {
  size_t n = 0;
  for (const auto& [first, end] : ranges) n += end - first;
  return n;
}

}  // namespace

std::optional<MovedTriangles> movedTriangles(const StageContext& ctx, bool emissive) {
  const PreviousFrame* p = ctx.previous;
  if (p == nullptr || p->scene == nullptr || p->triangles == nullptr) return std::nullopt;
  const Scene& before = *p->scene;
  const GridSpec &g0 = before.grid, &g1 = ctx.scene.grid;
  if (g0.resolution != g1.resolution || g0.min != g1.min || g0.size != g1.size ||
      before.meshes.size() != ctx.scene.meshes.size() ||
      p->triangles->meshFirst.size() != ctx.triangles.meshFirst.size() ||
      p->triangles->emissionScale != ctx.triangles.emissionScale)
    return std::nullopt;
  for (const BufferId id :
       {BufferId::common_voxelize_weight_sum, BufferId::common_voxelize_albedo_sum,
        BufferId::common_voxelize_normal_sum, BufferId::common_voxelize_opacity,
        BufferId::common_voxelize_albedo, BufferId::common_voxelize_normal})
    if (!p->stash.contains(id)) return std::nullopt;
  if (emissive != p->stash.contains(BufferId::common_voxelize_emission_sum) ||
      emissive != p->stash.contains(BufferId::common_voxelize_emission))
    return std::nullopt;
  MovedTriangles moved;
  for (size_t m = 0; m < ctx.scene.meshes.size(); ++m)
    if (before.meshes[m].positions != ctx.scene.meshes[m].positions) {
      moved.before.emplace_back(p->triangles->meshFirst[m], p->triangles->meshFirst[m + 1]);
      moved.now.emplace_back(ctx.triangles.meshFirst[m], ctx.triangles.meshFirst[m + 1]);
    }
  if (triangleCount(moved.before) + triangleCount(moved.now) >= ctx.triangles.triangles.size())
    return std::nullopt;
  return moved;
}

std::vector<shared::VoxelTriangle> trianglesIn(
    const VoxelTriangles& triangles, const std::vector<std::pair<size_t, size_t>>& ranges) {
  std::vector<shared::VoxelTriangle> out;
  for (const auto& [first, end] : ranges)
    out.insert(out.end(), triangles.triangles.begin() + ptrdiff_t(first),
               triangles.triangles.begin() + ptrdiff_t(end));
  return out;
}

}  // namespace voxgi
