#version 450 core
// Conservative voxelization, fragment stage: one invocation per (triangle, voxel column). Every
// layer of the column that the triangle may touch is decided by the shared separating-axis test
// and weighted by the exact clipped area, as cpu/voxelize.cpp does, and accumulated with integer
// image atomics in the same fixed point; a textured triangle's albedo and emission come from its
// textures (shared/voxelize_surface.h).
#include "shared/texture_layout.h"
#include "texture_access.glsl"
#include "shared/voxelize_surface.h"
#include "voxelize_accumulate.glsl"

flat in int gTriangle;
flat in ivec4 gColumns;

void main() {
  ivec2 column = ivec2(gl_FragCoord.xy);
  if (any(lessThan(column, gColumns.xy)) || any(greaterThan(column, gColumns.zw))) discard;
  VoxelTriangle t = triangles[gTriangle];
  ivec2 layers = columnLayers(t, column, uResolution);
  for (int k = layers.x; k <= layers.y; ++k) {
    ivec3 voxel = fromDominant(ivec3(column, k), t.dominantAxis);
    VoxelContribution c;
    if (conservativeContribution(t, voxel, c)) accumulate(voxel, c);
  }
}
