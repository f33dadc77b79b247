// What the shared kernels read in the octree on the GPU (the CPU's cpu/svo/svo_volumes.h
// SvoVolumes): the tree's node words and leaf tiles, the leaves' attributes, and the radiance of
// pyramid level 0 (the leaves) and of the node levels, each found by walking the tree.
#include "svo_tree.glsl"
layout(std430, binding = 1) readonly buffer LeafTiles { uint leafTiles[]; };
// per leaf slot (8 a leaf tile): albedo sum and opacity, normal sum, emission sum (RGBA each, as
// two words of halves: the geometry pool, shared/half_float.h's packHalves)
layout(std430, binding = 2) readonly buffer LeafValues { uvec2 leafValues[]; };
#define SVO_SOURCE_BINDING 3
#define SVO_FACES_BINDING 4
#include "svo_pyramid.glsl"

vec4 leafAlbedo(uint s) { return unpackHalves(leafValues[3u * s]); }
vec3 leafNormal(uint s) { return unpackHalves(leafValues[3u * s + 1u]).xyz; }
vec3 leafEmission(uint s) { return unpackHalves(leafValues[3u * s + 2u]).xyz; }

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
