// What the shared kernels read in the octree on the GPU (the CPU's cpu/svo/leaf_light.h
// SvoVolumes): the tree's node words and leaf tiles, the leaves' attributes, and the radiance of
// pyramid level 0 (the leaves) and of the node levels, each found by walking the tree.
layout(std430, binding = 0) readonly buffer Nodes { uint nodes[]; };
layout(std430, binding = 1) readonly buffer LeafTiles { uint leafTiles[]; };
// per leaf slot (8 a leaf tile): albedo sum and opacity, normal sum, emission sum (vec4 each)
layout(std430, binding = 2) readonly buffer LeafValues { vec4 leafValues[]; };
layout(std430, binding = 3) readonly buffer Source { vec4 source[]; };  // pyramid level 0
// six faces per node, by node index
layout(std430, binding = 4) buffer NodeFaces { vec4 nodeFaces[]; };
uniform int uDepth;

uint svoNodeWord(uint i) { return nodes[i]; }
#include "shared/svo/svo_layout.h"

// The value slot of voxel v of tree `level`: node index (node levels) or leaf slot; kSvoNull if
// its tile does not exist.
uint slotOf(int level, ivec3 v) {
  uint t = svoFindTile(level, uvec3(v >> 1));
  return t == kSvoNull ? kSvoNull : t * 8u + localId(uvec3(v));
}

vec4 leafAlbedo(uint s) { return leafValues[3u * s]; }
vec3 leafNormal(uint s) { return leafValues[3u * s + 1u].xyz; }
vec3 leafEmission(uint s) { return leafValues[3u * s + 2u].xyz; }

float opacityAt(ivec3 v) {
  uint s = slotOf(uDepth, v);
  return s == kSvoNull ? 0.0f : min(leafAlbedo(s).a, 1.0f);
}
vec3 albedoAt(ivec3 v) {
  uint s = slotOf(uDepth, v);
  if (s == kSvoNull) return vec3(0.0f);
  vec4 a = leafAlbedo(s);
  if (a.a <= 0.0f) return vec3(0.0f);
  precise vec3 albedo = a.rgb / a.a;
  return albedo;
}
vec3 normalAt(ivec3 v) {
  uint s = slotOf(uDepth, v);
  return s == kSvoNull ? vec3(0.0f) : leafNormal(s);
}
vec3 emissionAt(ivec3 v) {
  uint s = slotOf(uDepth, v);
  if (s == kSvoNull) return vec3(0.0f);
  float a = leafAlbedo(s).a;
  if (a <= 0.0f) return vec3(0.0f);
  precise vec3 emission = leafEmission(s) / a;
  return emission;
}
vec4 pyramidAt(int level, int face, ivec3 v) {
  uint s = slotOf(uDepth - level, v);
  if (s == kSvoNull) return vec4(0.0f);
  return level == 0 ? source[s] : nodeFaces[6u * s + uint(face)];
}
bool cellEmpty(int level, ivec3 i) { return false; }

// The leaf of slot s that holds samples, as a coordinate; false for an empty leaf.
bool realLeaf(uint s, out ivec3 v) {
  uint tile = s / 8u;
  uint local = s % 8u;
  uint parent = leafTiles[tile * uint(kTileWords) + uint(kTileParent)];
  uint mask = (nodes[parent * uint(kNodeWords) + uint(kNodeFlags)] >> kNodeChildShift) & 255u;
  if (((mask >> local) & 1u) == 0u) return false;
  v = ivec3(mortonDecode((leafTiles[tile * uint(kTileWords) + uint(kTileKey)] << 3) | local));
  return true;
}
