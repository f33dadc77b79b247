#version 450 core
// Bricks of one tree level (cpu/svo/bricks.h, completeBricks): each tile's 2^3 values of uFaces
// RGBA faces as a 3^3 brick whose positive boundary comes from the tiles the parent's + neighbours
// lead to (0 where there is none). The leaves' values (uFaces 1: per leaf slot) or the node levels'
// six faces (uFaces 6: per node, every node tile at once). One invocation per brick texel.
layout(local_size_x = 64) in;
#include "svo_tree.glsl"

// the tile records (leaf tiles, or node tiles)
layout(std430, binding = 1) readonly buffer Tiles { uint tiles[]; };
// RGBA values as two words of halves (shared/half_float.h, packHalves), copied as they are
layout(std430, binding = 2) readonly buffer Interior { uvec2 interior[]; };  // uFaces a voxel
layout(std430, binding = 3) writeonly buffer Bricks { uvec2 bricks[]; };     // 27 x uFaces a tile
uniform uint uCount;  // texels: tiles x 27
uniform uint uFaces;

void main() {
  uint e = gl_GlobalInvocationID.x + gl_NumWorkGroups.x * 64u * gl_GlobalInvocationID.y;
  if (e >= uCount) return;
  uint tile = e / uint(kBrickTexels);
  int texel = int(e % uint(kBrickTexels));
  ivec3 at = ivec3(texel % 3, (texel / 3) % 3, texel / 9);
  uint source = tile;
  if (at.x == 2 || at.y == 2 || at.z == 2) {
    uint node = tiles[tile * uint(kTileWords) + uint(kTileParent)];
    for (int a = 0; a < 3 && node != kSvoNull; ++a)
      if (at[a] == 2) node = nodes[node * uint(kNodeWords) + uint(kNodeNeighbour + 2 * a)];
    source = node == kSvoNull ? kSvoNull : nodes[node * uint(kNodeWords) + uint(kNodeChild)];
  }
  uint voxel = source * 8u + localId(uvec3(at % 2));
  for (uint f = 0u; f < uFaces; ++f)
    bricks[e * uFaces + f] = source == kSvoNull ? uvec2(0u) : interior[voxel * uFaces + f];
}
