#version 450 core
// The direct light of every leaf that holds samples (shaders/shared/cone/voxel_light.h
// through the octree, shaders/svo/svo_volumes.glsl): emission plus the analytic lights with voxel
// visibility, premultiplied by the clamped opacity. One invocation per leaf slot.
layout(local_size_x = 64) in;
#include "shared/lighting.h"
#include "svo_volumes.glsl"

LightData lightAt(int i);  // defined below, after the light block

#include "shared/cone/voxel_light.h"

layout(std430, binding = 5) readonly buffer Lights {
  LightVoxelsParams params;
  LightData lights[];
};
layout(std430, binding = 6) writeonly buffer Direct { uvec2 direct[]; };  // halves (packHalves)
uniform uint uCount;

LightData lightAt(int i) { return lights[i]; }

void main() {
  uint s = gl_GlobalInvocationID.x + gl_NumWorkGroups.x * 64u * gl_GlobalInvocationID.y;
  if (s >= uCount) return;
  ivec3 v;
  direct[s] = realLeaf(s, v) ? packHalves(lightVoxel(v, params)) : uvec2(0u);
}
