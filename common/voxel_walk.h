// The (voxel, contribution) pairs one triangle gives in each voxelize mode, from the shared kernel
// (shaders/shared/voxelize_kernel.h): the CPU voxelize stage accumulates them, and the check for
// repeated triangles (common/voxel_overflow.h) sums one copy's.
#pragma once

#include <algorithm>
#include <cmath>

#include "common/texture.h"
#include "shaders/shared/voxelize_surface.h"

namespace voxgi {

// Conservative mode: every voxel the triangle touches, with its area in that voxel.
// sink(const glm::ivec3& voxel, const shared::VoxelContribution& c), once per voxel.
template <class Sink>
void conservativeWalk(const shared::VoxelTriangle& t, int n, const TextureAccess& textures,
                      Sink&& sink) {
  const unsigned axis = t.dominantAxis;
  const glm::vec3 p0 = shared::toDominant(glm::vec3(t.v0), axis);
  const glm::vec3 p1 = shared::toDominant(glm::vec3(t.v1), axis);
  const glm::vec3 p2 = shared::toDominant(glm::vec3(t.v2), axis);
  const glm::vec3 lo = glm::min(p0, glm::min(p1, p2));
  const glm::vec3 hi = glm::max(p0, glm::max(p1, p2));
  // Closed columns: column u spans [u, u+1], so it touches [lo, hi] iff ceil(lo) - 1 <= u <=
  // floor(hi).
  const int u0 = std::max(0, int(std::ceil(lo.x)) - 1), u1 = std::min(n - 1, int(std::floor(hi.x)));
  const int w0 = std::max(0, int(std::ceil(lo.y)) - 1), w1 = std::min(n - 1, int(std::floor(hi.y)));
  shared::VoxelContribution c{};
  for (int cw = w0; cw <= w1; ++cw)
    for (int cu = u0; cu <= u1; ++cu) {
      const glm::ivec2 layers = shared::columnLayers(t, {cu, cw}, n);
      for (int k = layers.x; k <= layers.y; ++k) {
        const glm::ivec3 voxel = shared::fromDominant({cu, cw, k}, axis);
        if (shared::conservativeContribution(textures, t, voxel, c)) sink(voxel, c);
      }
    }
}

// Antialiased mode: each sample's tent weights into the eight voxels around it (inside the grid).
// sink(voxel, contribution), possibly several times per voxel.
template <class Sink>
void antialiasedWalk(const shared::VoxelTriangle& t, int n, const TextureAccess& textures,
                     Sink&& sink) {
  const auto inside = [n](const glm::ivec3& v) {
    return v.x >= 0 && v.y >= 0 && v.z >= 0 && v.x < n && v.y < n && v.z < n;
  };
  for (int i = 0; i < int(t.subdivision); ++i)
    for (int k = 0; k < shared::antialiasedRowSamples(t, i); ++k) {
      const glm::vec2 b = shared::antialiasedRowBarycentric(t, i, k);
      const glm::vec3 p = shared::antialiasedSample(t, b);
      const glm::ivec3 base = shared::tentBase(p);
      for (int corner = 0; corner < 8; ++corner) {
        const glm::ivec3 voxel = shared::tentCorner(base, corner);
        if (!inside(voxel)) continue;
        const unsigned w = shared::tentWeight(t, p, base, corner);
        if (w != 0u) sink(voxel, shared::surfaceContribution(textures, t, w, b));
      }
    }
}

}  // namespace voxgi
