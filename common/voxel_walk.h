// The (voxel, contribution) pairs one triangle gives in each voxelize mode, from the shared kernel
// (shaders/shared/voxelize_kernel.h): the CPU voxelize stage accumulates them, and the check for
// repeated triangles (common/voxel_overflow.h) sums one copy's. The candidates, cheaper, are where
// the CPU stage marks the blocks its sums will need.
#pragma once

#include <algorithm>
#include <cmath>

#include "common/texture.h"
#include "shaders/shared/voxelize_surface.h"

namespace voxgi {

// Conservative mode's candidates: the voxels of each column that the layers the triangle's plane
// crosses there, a superset of the voxels it touches. visit(const glm::ivec3& voxel).
template <class Visit>
void conservativeCandidates(const shared::VoxelTriangle& t, int n, Visit&& visit) {
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
  for (int cw = w0; cw <= w1; ++cw)
    for (int cu = u0; cu <= u1; ++cu) {
      const glm::ivec2 layers = shared::columnLayers(t, {cu, cw}, n);
      for (int k = layers.x; k <= layers.y; ++k) visit(shared::fromDominant({cu, cw, k}, axis));
    }
}

// Conservative mode: every voxel the triangle touches, with its area in that voxel.
// sink(const glm::ivec3& voxel, const shared::VoxelContribution& c), once per voxel.
template <class Sink>
void conservativeWalk(const shared::VoxelTriangle& t, int n, const TextureAccess& textures,
                      Sink&& sink) {
  shared::VoxelContribution c{};
  conservativeCandidates(t, n, [&](const glm::ivec3& voxel) {
    if (shared::conservativeContribution(textures, t, voxel, c)) sink(voxel, c);
  });
}

// Antialiased mode's samples and the eight voxels around each (inside the grid): visit(voxel,
// sample position, tent base, corner, barycentric coordinates).
template <class Visit>
void antialiasedCorners(const shared::VoxelTriangle& t, int n, Visit&& visit) {
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
        if (inside(voxel)) visit(voxel, p, base, corner, b);
      }
    }
}

// Antialiased mode's candidates: the voxels around its samples, a superset of those its tents
// weigh. visit(const glm::ivec3& voxel).
template <class Visit>
void antialiasedCandidates(const shared::VoxelTriangle& t, int n, Visit&& visit) {
  antialiasedCorners(t, n,
                     [&](const glm::ivec3& voxel, const glm::vec3&, const glm::ivec3&, int,
                         const glm::vec2&) { visit(voxel); });
}

// Antialiased mode: each sample's tent weights into the eight voxels around it (inside the grid).
// sink(voxel, contribution), possibly several times per voxel.
template <class Sink>
void antialiasedWalk(const shared::VoxelTriangle& t, int n, const TextureAccess& textures,
                     Sink&& sink) {
  antialiasedCorners(t, n,
                     [&](const glm::ivec3& voxel, const glm::vec3& p, const glm::ivec3& base,
                         int corner, const glm::vec2& b) {
                       const unsigned w = shared::tentWeight(t, p, base, corner);
                       if (w != 0u) sink(voxel, shared::surfaceContribution(textures, t, w, b));
                     });
}

}  // namespace voxgi
