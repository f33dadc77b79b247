#include "common/voxelize_update.h"

#include <limits>

namespace voxgi {

namespace {

size_t triangleCount(const std::vector<std::pair<size_t, size_t>>& ranges) {
  size_t n = 0;
  for (const auto& [first, end] : ranges) n += end - first;
  return n;
}

// The meshes that moved since the frame before, as triangle ranges of both frames; nullopt when
// there is no frame before or it cannot be compared mesh by mesh.
std::optional<MovedTriangles> movedMeshes(const StageContext& ctx) {
  const PreviousFrame* p = ctx.previous;
  if (p == nullptr || p->scene == nullptr || p->triangles == nullptr) return std::nullopt;
  const Scene& before = *p->scene;
  const GridSpec &g0 = before.grid, &g1 = ctx.scene.grid;
  if (g0.resolution != g1.resolution || g0.min != g1.min || g0.size != g1.size ||
      before.meshes.size() != ctx.scene.meshes.size() ||
      p->triangles->meshFirst.size() != ctx.triangles.meshFirst.size() ||
      p->triangles->emissionScale != ctx.triangles.emissionScale)
    return std::nullopt;
  MovedTriangles moved;
  for (size_t m = 0; m < ctx.scene.meshes.size(); ++m)
    if (before.meshes[m].positions != ctx.scene.meshes[m].positions) {
      moved.before.emplace_back(p->triangles->meshFirst[m], p->triangles->meshFirst[m + 1]);
      moved.now.emplace_back(ctx.triangles.meshFirst[m], ctx.triangles.meshFirst[m + 1]);
    }
  return moved;
}

void grow(VoxelBox& box, const VoxelTriangles& triangles,
          const std::vector<std::pair<size_t, size_t>>& ranges) {
  for (const auto& [first, end] : ranges)
    for (size_t t = first; t < end; ++t)
      for (const glm::vec3& v :
           {triangles.triangles[t].v0, triangles.triangles[t].v1, triangles.triangles[t].v2}) {
        box.low = glm::min(box.low, v);
        box.high = glm::max(box.high, v);
      }
}

}  // namespace

std::optional<MovedTriangles> movedTriangles(const StageContext& ctx, bool emissive) {
  std::optional<MovedTriangles> moved = movedMeshes(ctx);
  if (!moved) return std::nullopt;
  const PreviousFrame* p = ctx.previous;
  for (const BufferId id :
       {BufferId::common_voxelize_weight_sum, BufferId::common_voxelize_albedo_sum,
        BufferId::common_voxelize_normal_sum, BufferId::common_voxelize_opacity,
        BufferId::common_voxelize_albedo, BufferId::common_voxelize_normal})
    if (!p->stash.contains(id)) return std::nullopt;
  if (emissive != p->stash.contains(BufferId::common_voxelize_emission_sum) ||
      emissive != p->stash.contains(BufferId::common_voxelize_emission))
    return std::nullopt;
  if (triangleCount(moved->before) + triangleCount(moved->now) >= ctx.triangles.triangles.size())
    return std::nullopt;
  return moved;
}

std::optional<VoxelBox> changedVoxelBox(const StageContext& ctx) {
  const std::optional<MovedTriangles> moved = movedMeshes(ctx);
  if (!moved || moved->now.empty()) return std::nullopt;
  VoxelBox box{glm::vec3(std::numeric_limits<float>::infinity()),
               glm::vec3(-std::numeric_limits<float>::infinity())};
  grow(box, *ctx.previous->triangles, moved->before);
  grow(box, ctx.triangles, moved->now);
  if (!(box.low.x <= box.high.x)) return std::nullopt;  // the moved meshes hold no triangles
  box.low -= 1.0f;
  box.high += 1.0f;
  return box;
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
