#version 450 core
// The leaf bricks of a per-leaf RGBA value (cpu/svo/octree.h, completeBricks): each leaf tile's
// 2^3 values as a 3^3 brick whose positive boundary comes from the tiles the parent's + neighbours
// lead to (0 where there is none). One invocation per brick texel.
layout(local_size_x = 64) in;
#include "svo_tree.glsl"

layout(std430, binding = 1) readonly buffer LeafTiles { uint leafTiles[]; };
layout(std430, binding = 2) readonly buffer Interior { vec4 interior[]; };  // per leaf slot
layout(std430, binding = 3) writeonly buffer Bricks { vec4 bricks[]; };     // 27 a leaf tile
uniform uint uCount;  // texels: leaf tiles x 27

void main() {
  uint e = gl_GlobalInvocationID.x + gl_NumWorkGroups.x * 64u * gl_GlobalInvocationID.y;
  if (e >= uCount) return;
  uint tile = e / uint(kBrickTexels);
  int texel = int(e % uint(kBrickTexels));
  ivec3 at = ivec3(texel % 3, (texel / 3) % 3, texel / 9);
  uint source = tile;
  if (at.x == 2 || at.y == 2 || at.z == 2) {
    uint node = leafTiles[tile * uint(kTileWords) + uint(kTileParent)];
    for (int a = 0; a < 3 && node != kSvoNull; ++a)
      if (at[a] == 2) node = nodes[node * uint(kNodeWords) + uint(kNodeNeighbour + 2 * a)];
    source = node == kSvoNull ? kSvoNull : nodes[node * uint(kNodeWords) + uint(kNodeChild)];
  }
  bricks[e] = source == kSvoNull ? vec4(0.0f) : interior[source * 8u + localId(uvec3(at % 2))];
}
