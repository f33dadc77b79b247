#version 450 core
// One node level of the octree's six-face mipmap (shaders/shared/cone/mip.h): each node's
// faces from its child tile, the leaves' radiance (optionally weighted per face by their normals,
// shaders/shared/svo/mip_kernel.h) or the level below's faces, each face rounded to halves as the
// pool stores it. One invocation per node.
layout(local_size_x = 64) in;
#include "shared/svo/mip_kernel.h"
#include "svo_volumes.glsl"

uniform int uLevel;
uniform uint uFirst;  // the level's first node
uniform uint uCount;  // its nodes
uniform bool uNdfWeights;
uint gChild;  // the child tile of the node being mipmapped

vec4 childAt(int face, ivec3 c) {
  uint child = gChild * 8u + localId(uvec3(c));
  if (uLevel + 1 < uDepth) return unpackHalves(nodeFaces[6u * child + uint(face)]);
  vec4 v = unpackHalves(source[child]);
  return uNdfWeights ? ndfWeighted(v, leafNormal(child), face) : v;
}

#include "shared/cone/mip.h"

void main() {
  uint i = gl_GlobalInvocationID.x + gl_NumWorkGroups.x * 64u * gl_GlobalInvocationID.y;
  if (i >= uCount) return;
  uint node = uFirst + i;
  gChild = nodes[node * uint(kNodeWords) + uint(kNodeChild)];
  for (int face = 0; face < kFaces; ++face)
    nodeFaces[6u * node + uint(face)] =
        gChild == kSvoNull ? uvec2(0u) : packHalves(mipAnisotropic(ivec3(0), face));
}
