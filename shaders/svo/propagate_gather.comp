#version 450 core
// One gather at every leaf that holds samples (shaders/shared/cone/gather.h through the
// octree): the diffuse cones over the mipmap of the previous frame's radiance, giving the next
// frame's radiance and the gathered E / pi with the opacity (straight: the host premultiplies it,
// as the CPU does, and keeps it for propagate.carry). One invocation per leaf slot. The cones read
// the levels through their bricks.
layout(local_size_x = 64) in;
#include "shared/cone/cone_types.h"
#include "svo_volumes.glsl"

// The light as halves (shared/half_float.h, packHalves), as the CPU's pools round it.
layout(std430, binding = 6) readonly buffer Direct { uvec2 direct[]; };
// per leaf slot: the next radiance, then the gathered light (rgb) and the opacity (a)
layout(std430, binding = 7) writeonly buffer Frame { uvec2 frame[]; };
uniform uint uCount;

vec4 directAt(ivec3 v) {
  uint s = slotOf(uDepth, v);
  return s == kSvoNull ? vec4(0.0f) : unpackHalves(direct[s]);
}
ConeData coneAt(int i);  // defined below, after the cone block

// The source's levels as bricks (gpu/svo/bricks.cpp, completeBricks): the cones read a trilinear
// cell with one walk and eight texels, not a walk per texel.
layout(std430, binding = 8) readonly buffer LeafBricks { uvec2 leafBricks[]; };  // 27 a leaf tile
layout(std430, binding = 9) readonly buffer NodeBricks { uvec2 nodeBricks[]; };  // 27 x 6 a tile
vec4 svoBrickAt(int level, int face, uint tile, uint texel) {
  uint e = tile * uint(kBrickTexels) + texel;
  return unpackHalves(level == uDepth ? leafBricks[e] : nodeBricks[e * 6u + uint(face)]);
}
#include "shared/svo/svo_sample.h"
// Pyramid level `level` is tree level uDepth - level (svo_pyramid.glsl).
vec4 filterBrickCell(int level, int face, TrilinearCell c) {
  return svoFilterCell(uDepth - level, face, c);
}
#define VOXGI_BRICK_CELLS

#include "shared/cone/gather.h"

layout(std430, binding = 5) readonly buffer Cones {
  ConeTraceParams params;
  ConeData cones[];
};

ConeData coneAt(int i) { return cones[i]; }

void main() {
  uint s = gl_GlobalInvocationID.x + gl_NumWorkGroups.x * 64u * gl_GlobalInvocationID.y;
  if (s >= uCount) return;
  ivec3 v;
  if (!realLeaf(s, v)) {
    frame[2u * s] = uvec2(0u);
    frame[2u * s + 1u] = uvec2(0u);
    return;
  }
  vec3 g = gatherVoxel(v, params);
  vec4 d = unpackHalves(direct[s]);
  // The radiance reflects the gathered light as its pool stores it (halves), as the CPU's does.
  vec4 stored = roundToHalf4(vec4(g, d.a));
  frame[2u * s] = packHalves(addReflected(d, albedoAt(v), stored.rgb));
  frame[2u * s + 1u] = packHalves(stored);
}
