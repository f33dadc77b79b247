// Morton keys of the sparse voxel octree [Salm 2015, §4.3.1]: the bits of a node's coordinates at
// its level interleaved with x in the least significant bit (the thesis's Figure 4.6 in 2-D; its
// 3-D order is unstated, docs/svo.md): key = sum_b x_b << 3b | y_b << 3b+1 | z_b << 3b+2. A node's
// local id in its tile is key & 7 and its parent's key is key >> 3. Coordinates have at most 10
// bits, so keys fit a uint. Included by C++ and GLSL.
#ifndef VOXGI_MORTON_H
#define VOXGI_MORTON_H
#include "glsl_cpp.h"

VOXGI_NAMESPACE_BEGIN

// The low 10 bits of v moved to every third bit.
VOXGI_FN uint mortonSpread(uint v) {
  uint r = v & 0x3ffu;
  r = (r | (r << 16)) & 0x030000ffu;
  r = (r | (r << 8)) & 0x0300f00fu;
  r = (r | (r << 4)) & 0x030c30c3u;
  r = (r | (r << 2)) & 0x09249249u;
  return r;
}

// Every third bit of v, from bit 0, gathered into the low 10 bits.
VOXGI_FN uint mortonCompact(uint v) {
  uint r = v & 0x09249249u;
  r = (r | (r >> 2)) & 0x030c30c3u;
  r = (r | (r >> 4)) & 0x0300f00fu;
  r = (r | (r >> 8)) & 0x030000ffu;
  r = (r | (r >> 16)) & 0x3ffu;
  return r;
}

VOXGI_FN uint mortonEncode(uvec3 c) {
  return mortonSpread(c.x) | (mortonSpread(c.y) << 1) | (mortonSpread(c.z) << 2);
}

VOXGI_FN uvec3 mortonDecode(uint key) {
  return uvec3(mortonCompact(key), mortonCompact(key >> 1), mortonCompact(key >> 2));
}

// The local id of a node in its tile from its position in the tile (each component 0 or 1).
VOXGI_FN uint localId(uvec3 c) {
  return (c.x & 1u) | ((c.y & 1u) << 1) | ((c.z & 1u) << 2);
}

VOXGI_NAMESPACE_END
#endif
