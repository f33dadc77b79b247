#version 450 core
// build on the GPU (docs/svo.md): the octree's structure allocated with atomics, level by
// level, then the leaf sums. Each dispatch is one pass (uPass); the host reads a counter between
// passes to size the next dispatch and grow the pools to the tiles actually allocated. Tiles come
// out in whatever order the invocations run; the host puts them in the canonical order
// (common/svo/canonical.h), which the diff compares.
layout(local_size_x = 64) in;
#include "shared/svo/build_kernel.h"

const int kPassMark = 0;          // per sample: mark the leaves its RoI touches
const int kPassCountLeafTiles = 1;  // per mark word: count marked leaf tiles
const int kPassListLeafTiles = 2;   // per mark word: list them (key, leaf mask)
const int kPassReal = 3;          // per listed leaf tile: its node of level uLevel is real
const int kPassBorderNodes = 4;   // per node of level uLevel: the border tiles it needs
const int kPassBorderLeaves = 5;  // per listed leaf tile: the border leaf tiles it needs
const int kPassCountChildren = 6;  // per node of level uLevel: needs a child tile it lacks
const int kPassAllocate = 7;      // per node of level uLevel: allocate that child tile
const int kPassNeighbours = 8;    // per node: its six neighbours
const int kPassAccumulate = 9;    // per sample: fixed-point sums into its leaves

// A node flag of the build only: a border tile is needed below this node (cleared by the
// neighbour pass, which visits every node last).
const uint kNodeNeedsBorder = 2u;

uniform int uPass;
uniform int uDepth;
uniform int uLevel;
uniform uint uFirst;  // first node (node passes) of the dispatch
uniform uint uCount;  // invocations that work
uniform float uScale;

layout(std430, binding = 0) readonly buffer Samples { SvoSample samples[]; };
layout(std430, binding = 1) buffer Marks { uint marks[]; };  // a byte per leaf tile key
layout(std430, binding = 2) buffer LeafList { uvec2 leafList[]; };
// 0: node tiles, 1: leaf tiles, 2: listed leaf tiles, 3: pass count, 4: overflow
layout(std430, binding = 3) buffer Counters { uint counters[]; };
layout(std430, binding = 4) buffer Nodes { uint nodes[]; };
layout(std430, binding = 5) buffer Tiles { uint tiles[]; };
layout(std430, binding = 6) buffer LeafTiles { uint leafTiles[]; };
layout(std430, binding = 7) buffer Sums { int sums[]; };

uint svoNodeWord(uint i) {
  return nodes[i];
}
#include "shared/svo/svo_layout.h"

// The nodes whose local coordinate is 0 on every axis of the set s (x 1, y 2, z 4).
uint nodesAtZero(uint s) {
  uint m = 0u;
  for (uint n = 0u; n < 8u; ++n)
    if ((n & s) == 0u) m |= 1u << n;
  return m;
}

// Marks, as needing a border child, the node of `level` at coordinate c.
void needBorder(int level, ivec3 c) {
  uint t = svoFindTile(level, uvec3(c >> 1));
  if (t == kSvoNull) return;  // cannot happen: the rule one level up made the tile
  atomicOr(nodes[(t * 8u + localId(uvec3(c))) * uint(kNodeWords) + uint(kNodeFlags)],
           kNodeNeedsBorder);
}

// The border tiles of tile coordinate `tile` (keys of one level) that nodes `mask` require.
void needBorders(int parentLevel, ivec3 tile, uint mask) {
  for (uint s = 1u; s < 8u; ++s) {
    if ((mask & nodesAtZero(s)) == 0u) continue;
    ivec3 d = tile - ivec3(int(s & 1u), int((s >> 1) & 1u), int((s >> 2) & 1u));
    if (d.x < 0 || d.y < 0 || d.z < 0) continue;
    needBorder(parentLevel, d);
  }
}

// The leaf of corner c of a sample's RoI, or -1 when the RoI does not cover it.
ivec3 cornerLeaf(SplatAxis x, SplatAxis y, SplatAxis z, ivec3 c, int n) {
  ivec3 leaf = ivec3(x.lo, y.lo, z.lo) + c;
  bool covers = (c.x == 0 ? x.w0 : x.w1) > 0.0f && (c.y == 0 ? y.w0 : y.w1) > 0.0f &&
                (c.z == 0 ? z.w0 : z.w1) > 0.0f;
  if (!covers || any(lessThan(leaf, ivec3(0))) || any(greaterThanEqual(leaf, ivec3(n))))
    return ivec3(-1);
  return leaf;
}

bool needsChild(uint node) {
  uint flags = nodes[node * uint(kNodeWords) + uint(kNodeFlags)];
  return (flags & (kNodeReal | kNodeNeedsBorder)) != 0u &&
         nodes[node * uint(kNodeWords) + uint(kNodeChild)] == kSvoNull;
}

void main() {
  uint i = gl_GlobalInvocationID.x + gl_NumWorkGroups.x * 64u * gl_GlobalInvocationID.y;
  if (i >= uCount) return;
  int n = 1 << uDepth;
  if (uPass == kPassMark || uPass == kPassAccumulate) {
    SvoSample s = samples[i];
    if (!splatInDomain(s.position.xyz, float(n))) return;
    SplatAxis x = splatAxis(s.position.x, s.edge);
    SplatAxis y = splatAxis(s.position.y, s.edge);
    SplatAxis z = splatAxis(s.position.z, s.edge);
    for (int k = 0; k < 8; ++k) {
      ivec3 c = ivec3(k & 1, (k >> 1) & 1, k >> 2);
      ivec3 leaf = cornerLeaf(x, y, z, c, n);
      if (leaf.x < 0) continue;
      uint key = mortonEncode(uvec3(leaf));
      if (uPass == kPassMark) {
        uint tileKey = key >> 3;
        atomicOr(marks[tileKey >> 2], 1u << (8u * (tileKey & 3u) + (key & 7u)));
        continue;
      }
      float w = splatWeight(x, y, z, s.density, c);
      uint tile = svoFindTile(uDepth, uvec3(leaf >> 1));
      int at = int((tile * 8u + (key & 7u)) * uint(kSumWords));
      int opacity = fixedRound(w, 1.0f, uScale);
      int before = atomicAdd(sums[at + kSumOpacity], opacity);
      if (before > 2147483647 - opacity) atomicOr(counters[4], 1u);
      for (int ch = 0; ch < 3; ++ch) {
        atomicAdd(sums[at + kSumAlbedo + ch], fixedRound(w, s.albedo[ch], uScale));
        atomicAdd(sums[at + kSumNormal + ch], fixedRound(w, s.normal[ch], uScale));
        atomicAdd(sums[at + kSumEmission + ch], fixedRound(w, s.emission[ch], uScale));
      }
    }
    return;
  }
  if (uPass == kPassCountLeafTiles || uPass == kPassListLeafTiles) {
    uint word = marks[i];
    for (uint b = 0u; b < 4u; ++b) {
      uint mask = (word >> (8u * b)) & 255u;
      if (mask == 0u) continue;
      uint slot = atomicAdd(counters[2], 1u);
      if (uPass == kPassListLeafTiles) leafList[slot] = uvec2(4u * i + b, mask);
    }
    return;
  }
  if (uPass == kPassReal || uPass == kPassBorderLeaves) {
    uvec2 entry = leafList[i];
    if (uPass == kPassBorderLeaves) {
      needBorders(uDepth - 1, ivec3(mortonDecode(entry.x)), entry.y);
      return;
    }
    // The leaf tile's ancestor node at uLevel, and which of that node's children is real.
    uint key = entry.x >> uint(3 * (uDepth - 1 - uLevel));
    uint tile = svoFindTile(uLevel, mortonDecode(key >> 3));
    uint child = uLevel == uDepth - 1 ? entry.y << kNodeChildShift
                                      : 1u << (kNodeChildShift +
                                               ((entry.x >> uint(3 * (uDepth - 2 - uLevel))) & 7u));
    atomicOr(nodes[(tile * 8u + (key & 7u)) * uint(kNodeWords) + uint(kNodeFlags)],
             kNodeReal | child);
    return;
  }
  uint node = uFirst + i;
  uint tile = node / 8u;
  uint key = (tiles[tile * uint(kTileWords) + uint(kTileKey)] << 3) | (node & 7u);
  if (uPass == kPassBorderNodes) {
    if ((nodes[node * uint(kNodeWords) + uint(kNodeFlags)] & kNodeReal) == 0u) return;
    needBorders(uLevel - 1, ivec3(mortonDecode(key >> 3)), 1u << (node & 7u));
  } else if (uPass == kPassCountChildren) {
    if (needsChild(node)) atomicAdd(counters[3], 1u);
  } else if (uPass == kPassAllocate) {
    if (!needsChild(node)) return;
    bool leaves = uLevel + 1 == uDepth;
    uint t = atomicAdd(counters[leaves ? 1 : 0], 1u);
    uint flags = nodes[node * uint(kNodeWords) + uint(kNodeFlags)];
    uvec4 record = uvec4(uint(uLevel + 1), key, node, (flags & kNodeReal) != 0u ? 0u : kTileBorder);
    for (int w = 0; w < kTileWords; ++w) {
      if (leaves)
        leafTiles[t * uint(kTileWords) + uint(w)] = record[w];
      else
        tiles[t * uint(kTileWords) + uint(w)] = record[w];
    }
    nodes[node * uint(kNodeWords) + uint(kNodeChild)] = t;
  } else if (uPass == kPassNeighbours) {
    int level = int(tiles[tile * uint(kTileWords) + uint(kTileLevel)]);
    ivec3 c = ivec3(mortonDecode(key));
    for (int f = 0; f < 6; ++f) {
      ivec3 d = c;
      d[f / 2] += f % 2 == 0 ? 1 : -1;
      uint pointer = kSvoNull;
      if (d[f / 2] >= 0 && d[f / 2] < (1 << level)) {
        uint t = svoFindTile(level, uvec3(d >> 1));
        if (t != kSvoNull) pointer = t * 8u + localId(uvec3(d));
      }
      nodes[node * uint(kNodeWords) + uint(kNodeNeighbour + f)] = pointer;
    }
    nodes[node * uint(kNodeWords) + uint(kNodeFlags)] &= ~kNodeNeedsBorder;
  }
}
