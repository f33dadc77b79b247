// Trilinear samples of the sparse voxel octree's bricks (svo_layout.h), shared by every stage that
// samples a level: one walk from the root to the tile, eight texels of its brick. Bricks are read
// through FETCH(svoBrickAt)(level, face, tile, texel index). Included by C++ and GLSL.
#ifndef VOXGI_SVO_SAMPLE_H
#define VOXGI_SVO_SAMPLE_H
#include "../trilinear.h"
#include "svo_layout.h"

VOXGI_NAMESPACE_BEGIN

// The face FETCH(svoBrickAt) is asked for when shading samples the leaves' gathered light
// (shade_kernel.h), so that a pass whose cones also read the radiance's bricks tells the two apart.
const int kSvoGatheredFace = -1;

// Texel `texel` of the brick of `tile` at `level` (FETCH(svoBrickAt)(level, face, tile, texel
// index)); 0 without a tile or for a texel left of the brick (outside the grid's low faces).
VOLUME_FN vec4 svoBrickVoxel(VOLUMES_IN int level, int face, uint tile, ivec3 texel) {
  if (tile == kSvoNull || texel.x < 0 || texel.y < 0 || texel.z < 0) return vec4(0.0f);
  return FETCH(svoBrickAt)(level, face, tile, brickTexel(texel));
}

// Trilinear sample of one face of tree `level` over cell c (from trilinearCell in that level's
// voxel units): one tile lookup, eight texels of its brick, blended as the dense pyramid blends
// (trilinear.h). Equals the dense, zero-padded level's sample: the brick of tile floor(base / 2)
// holds base and base + 1 on each axis, and a cell left of the grid (base -1) reads tile 0's
// texels with the missing side 0.
VOLUME_FN vec4 svoFilterCell(VOLUMES_IN int level, int face, TrilinearCell c) {
  ivec3 t = max(c.base, ivec3(0)) >> 1;
  uint tile = svoFindTile(VOLUMES level, uvec3(t));
  ivec3 o = c.base - t * 2;
  vec4 c000 = svoBrickVoxel(VOLUMES level, face, tile, o);
  vec4 c100 = svoBrickVoxel(VOLUMES level, face, tile, o + ivec3(1, 0, 0));
  vec4 c010 = svoBrickVoxel(VOLUMES level, face, tile, o + ivec3(0, 1, 0));
  vec4 c110 = svoBrickVoxel(VOLUMES level, face, tile, o + ivec3(1, 1, 0));
  vec4 c001 = svoBrickVoxel(VOLUMES level, face, tile, o + ivec3(0, 0, 1));
  vec4 c101 = svoBrickVoxel(VOLUMES level, face, tile, o + ivec3(1, 0, 1));
  vec4 c011 = svoBrickVoxel(VOLUMES level, face, tile, o + ivec3(0, 1, 1));
  vec4 c111 = svoBrickVoxel(VOLUMES level, face, tile, o + ivec3(1, 1, 1));
  return blendCell(c000, c100, c010, c110, c001, c101, c011, c111, c.f);
}

VOXGI_NAMESPACE_END
#endif
